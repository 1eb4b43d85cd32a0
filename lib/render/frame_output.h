// Where rpict's pictures go: concatenated on the standard output, or into files named by -o — a printf
// pattern given the frame number ("frame%03d.hdr") — as Radiance pictures or, for names ending in .exr,
// OpenEXR. As Radiance's rpict, a file is never overwritten: a sequence skips frames whose file exists (so
// several processes can share one sequence), a single picture refuses. A file appears whole or not at all.
#pragma once
#include <string>
#include <vector>

#include "io/picture.h"
#include "render/picture_renderer.h"

namespace brume {

// The file name of frame `number`: the pattern's one integer conversion (%d, %i, with flags and width)
// filled in, "%%" as '%'. Throws Error on any other conversion.
std::string frameFileName(const std::string& pattern, int number);

// Whether the pattern holds an integer conversion (names differ from frame to frame).
bool namesFrames(const std::string& pattern);

// Creates `path` empty and exclusively, claiming the frame; false if it exists. Throws Error when it
// cannot be created for another reason.
bool claimFile(const std::string& path);

// Writes `picture` to `path` (claimed or not) through a temporary file renamed into place: Radiance's
// format, or OpenEXR (half or float pixels) when the name ends in .exr — with `spectra`, a spectral OpenEXR
// (spectral_picture.h) whose bands hold spectral radiance in W·m⁻²·sr⁻¹·nm⁻¹.
void writePictureFile(const std::string& path, const Picture& picture, bool exrFloat,
                      const PixelSpectra* spectra = nullptr);

// Writes a depth buffer (-z): one 32-bit float per pixel, top row first, as Radiance's pinterp reads; whole
// or not at all.
void writeDepthFile(const std::string& path, const std::vector<float>& depth);

}  // namespace brume
