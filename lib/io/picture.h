// Pictures: Radiance's RGBE/XYZE files (run-length encoded or flat, any of the eight scan orders) and, read
// through the OpenEXR library, OpenEXR files. Pixels are linear floats, three per pixel, top row first.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace brume {

struct Picture {
    int width = 0, height = 0;
    std::vector<float> pixels;  // width × height × 3, rows from the top, each left to right
    bool xyz = false;           // XYZE rather than RGBE
    double pixelAspect = 1;     // PIXASPECT= (height/width of a pixel), product of all such lines
    double exposure = 1;        // EXPOSURE=, product of all such lines (pixels are as stored, not divided)
    std::vector<std::string> header;  // the information header's lines, without newlines

    float* at(int x, int y) { return &pixels[3 * (size_t(y) * width + x)]; }
    const float* at(int x, int y) const { return &pixels[3 * (size_t(y) * width + x)]; }
};

// Reads a picture, Radiance's or (by its magic number) OpenEXR. Throws Error naming the file on anything
// malformed or truncated.
Picture readPicture(const std::string& path);
Picture readRadiancePicture(std::istream& in, const std::string& name);

// Writes `picture` as a run-length encoded Radiance picture: "#?RADIANCE", the header lines, FORMAT=,
// the blank line, "-Y height +X width" and the scanlines.
void writeRadiancePicture(std::ostream& out, const Picture& picture);

}  // namespace brume
