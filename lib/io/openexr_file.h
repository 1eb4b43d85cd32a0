// What layouts of OpenEXR pictures build on (openexr_picture.cpp's R, G, B and spectral_picture.cpp's bands):
// a Picture's header lines as attributes and back, and its R, G, B written and read together with further
// channels, in one pass. Further channels are interleaved in memory as Picture::pixels has R, G, B:
// names.size() values per pixel, pixel-major, rows from the top.
#pragma once
#include <OpenEXR/ImfForward.h>

#include <string>
#include <vector>

#include "io/openexr_picture.h"

namespace brume {

// The header of `picture`'s file: its header lines as attributes, no channels yet. Throws
// std::runtime_error on a PIXASPECT= or EXPOSURE= that is not positive.
Imf::Header exrHeader(const Picture& picture);

// Writes `picture`'s R, G, B and the channels `moreNames` (values in `more`) under `header`, as half or float,
// through a temporary file renamed over `path` once complete. Throws std::exception with the reason.
void writeExrPicture(const std::string& path, Imf::Header header, const Picture& picture, ExrPixels pixels,
                     const std::vector<std::string>& moreNames = {}, const float* more = nullptr);

// A picture's size and header lines from its file's attributes, its pixels allocated but not read.
Picture exrPicture(const Imf::Header& header);

// Reads the picture's R, G, B (or its luminance and chroma), and the channels `moreNames` into `more`, as
// floats, exact whether stored as half or float.
void readExrPixels(Imf::InputFile& file, const std::string& path, Picture& picture,
                   const std::vector<std::string>& moreNames = {}, float* more = nullptr);

}  // namespace brume
