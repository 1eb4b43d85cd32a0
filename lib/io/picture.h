// Pictures: Radiance's RGBE/XYZE files (run-length encoded or flat, any of the eight scan orders) and, read
// through the OpenEXR library, OpenEXR files. Pixels are linear floats, three per pixel, top row first.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace brume {

// 256 M pixels, 3 GB of floats: beyond any real picture; the readers refuse larger ones before allocating.
inline constexpr double kMaxPicturePixels = double(1 << 28);

struct Picture {
    int width = 0, height = 0;
    std::vector<float> pixels;  // width × height × 3, rows from the top, each left to right
    bool xyz = false;           // XYZE rather than RGBE
    // What the readers found in the header's PIXASPECT= (height/width of a pixel) and EXPOSURE= lines (pixels
    // are as stored, not divided). The writers go by the header lines alone.
    double pixelAspect = 1;
    double exposure = 1;
    // The information header's lines, without newlines and without FORMAT= (the writers add it from `xyz`)
    std::vector<std::string> header;

    float* at(int x, int y) { return &pixels[3 * (size_t(y) * width + x)]; }
    const float* at(int x, int y) const { return &pixels[3 * (size_t(y) * width + x)]; }
};

// Reads a picture, Radiance's or (by its magic number) OpenEXR. Throws Error naming the file on anything
// malformed or truncated.
Picture readPicture(const std::string& path);
Picture readRadiancePicture(std::istream& in, const std::string& name);

// Radiance 6's hyperspectral pictures (FORMAT=Radiance_spectra, as rtrace -co -fc writes them): NCOMP
// mantissa bytes and a shared exponent per pixel, not run-length encoded; the bands evenly split the range
// from WAVELENGTH_SPLITS' first wavelength to its last (longest first, as Radiance writes them).
struct HyperspectralPicture {
    Picture picture;           // size, pixel aspect and header; no pixels
    int bands = 0;
    double first = 0, last = 0;  // nm: the outer edges of the first and the last band
    std::vector<float> values;   // width × height × bands, rows from the top
};
// Throws Error naming the file on anything malformed or truncated.
HyperspectralPicture readHyperspectralPicture(const std::string& path);
HyperspectralPicture readHyperspectralPicture(std::istream& in, const std::string& name);

// Writes `picture` as a run-length encoded Radiance picture: "#?RADIANCE", the header lines (without
// PRIMARIES= when XYZE), FORMAT=, the blank line, "-Y height +X width" and the scanlines, laid out as
// Radiance 6.1 lays them out. A later frame of a stream of frames (Radiance's rpict -S without -o) goes
// without the "#?RADIANCE" line: its header lines continue the first frame's, as Radiance's ra_rgbe expects.
void writeRadiancePicture(std::ostream& out, const Picture& picture, bool laterFrame = false);

}  // namespace brume
