// Matrices of Radiance's matrix tools (rmtxop, dctimestep, rcontrib's outputs, gendaymtx's skies): rows ×
// columns of elements of one or more components (RGB triples, spectral bands), and the operations rmtxop
// offers. Values are kept in single precision, as Radiance keeps them; sums are taken in double.
#pragma once
#include <string>
#include <vector>

namespace brume {

struct Matrix {
    int rows = 0, cols = 0, comps = 1;
    std::vector<float> values;       // row by row, each element's components together
    std::vector<std::string> info;   // header lines to pass on (not the size and format lines)

    // Adds a line saying what was done to the values, where the matrix has a history to add it to (as
    // rmtxop adds them).
    void note(const std::string& line) {
        if (!info.empty()) info.push_back(line);
    }

    Matrix() = default;
    Matrix(int rows, int cols, int comps) : rows(rows), cols(cols), comps(comps), values(size_t(rows) * cols * comps) {}
    float* at(int r, int c) { return &values[(size_t(r) * cols + c) * comps]; }
    const float* at(int r, int c) const { return &values[(size_t(r) * cols + c) * comps]; }
};

// The matrix product, component by component (both with the same components); throws Error when a's
// columns are not b's rows.
Matrix multiply(const Matrix& a, const Matrix& b);
Matrix transposed(const Matrix& m);
// Each output component a weighted sum of the input's: `weights` holds comps weights per output component
// (rmtxop -c); throws Error when their number is not a multiple of m.comps.
Matrix transformed(const Matrix& m, const std::vector<double>& weights);
// Scales by one factor, or by one per component (rmtxop -s).
void scale(Matrix& m, const std::vector<double>& factors);

enum class ElementOp { Add, Multiply, Divide };
// a op b element by element; b may have one component for all of a's (multiply and divide). Division by
// zero gives zero, a warning and a header line saying so, as rmtxop gives.
Matrix elementwise(const Matrix& a, const Matrix& b, ElementOp op);

}  // namespace brume
