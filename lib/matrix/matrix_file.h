// Radiance's matrix files: a header ("#?RADIANCE", lines passed on, NROWS=, NCOLS=, NCOMP=, BigEndian=,
// FORMAT=) and the elements row by row, as ASCII, native floats or doubles, or a picture (RGBE/XYZE, one
// pixel an element, the first row at the top). Inputs may lack the header when the reader is told the size
// and format (dctimestep -n -if).
#pragma once
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "matrix/matrix.h"

namespace brume {

enum class MatrixFormat { Ascii, Float, Double, Rgbe };

// "ascii", "float", "double", "32-bit_rle_rgbe".
std::string formatName(MatrixFormat f);

// What a headerless input is (a header, where there is one, says it all).
struct MatrixShape {
    std::optional<MatrixFormat> format;  // ASCII when unknown
    int cols = 0;                        // 0: unknown (the rows then from the count of values, or one row)
    int comps = 3;
};

// A matrix from a file, "-" (the standard input) or "!command" (its output), or a Klems BSDF's transmission
// matrix from an XML file (bsdf_matrix.h, as Radiance's rmtxop and dctimestep read them); `stored`, if given,
// receives the input's format. Throws Error naming the input on anything malformed, truncated or too short.
Matrix readMatrix(const std::string& spec, const MatrixShape& shape = {}, MatrixFormat* stored = nullptr);
// The same from bytes already read (`name` for messages).
Matrix parseMatrix(const std::string& bytes, const std::string& name, const MatrixShape& shape = {},
                   MatrixFormat* stored = nullptr);

// How ASCII elements are laid out: rmtxop's (each component " %.7e", a tab after each element) or
// dctimestep's ("%.6e" components apart by spaces, elements by tabs).
enum class AsciiLayout { Rmtxop, Dctimestep };

// How much of a picture's header writePicture writes: all of it, a later frame's of a stream of frames (without
// "#?RADIANCE": its lines continue the first frame's), or none (the resolution line and the pixels).
enum class PictureHeader { Whole, LaterFrame, None };
// A matrix of 3 components as an RGBE picture, its rows from the top, `lines` in its header. Throws Error,
// writing nothing, where a value is not finite or the matrix is not RGB.
void writePicture(std::FILE* out, const Matrix& m, const std::vector<std::string>& lines, PictureHeader header);

// Writes the header (unless `header` is false): "#?RADIANCE", `lines` (the command and the like), the
// matrix's info, its size, BigEndian= for binary values, FORMAT=; then the elements. Throws Error, writing
// nothing, where a value is not finite (an overflow).
void writeMatrix(std::FILE* out, const Matrix& m, MatrixFormat format, AsciiLayout layout,
                 const std::vector<std::string>& lines, bool header = true);

}  // namespace brume
