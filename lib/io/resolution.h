// A Radiance picture's resolution line ("-Y 480 +X 640"): the image size and the order in which its pixels
// are stored. The first axis named is the slow one; "-Y" scanlines run top to bottom, "+X" left to right.
#pragma once
#include <string>
#include <utility>

namespace brume {

struct Resolution {
    int width = 0, height = 0;
    bool transposed = false;  // scanlines are columns (the line names X first)
    bool flipX = false;       // x runs right to left
    bool flipY = false;       // the first scanline is the bottom one

    int scanlines() const { return transposed ? width : height; }
    int scanlineLength() const { return transposed ? height : width; }
    // The pixel (column from the left, row from the top) stored at position k of scanline s.
    std::pair<int, int> pixel(int s, int k) const;
    // Where pixel (x, y) (column from the left, row from the top) is stored: scanline × length + position.
    long storedIndex(int x, int y) const;
    // The line itself, e.g. "-Y 480 +X 640" (no newline).
    std::string line() const;
};

// Parses a resolution line; throws Error "name: bad resolution line ..." when it is not one. Sizes are
// limited to 2^20, beyond any real picture.
Resolution parseResolution(const std::string& line, const std::string& name);

}  // namespace brume
