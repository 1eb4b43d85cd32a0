// Pictures from views, as Radiance's rpict makes them: one ray per pixel through a jittered point of the
// pixel (-pj), optionally through a lens (-pd); with -ps > 1 a first pass samples every -ps-th pixel and the
// pixels between samples that agree within -pt are interpolated, the others traced.
// A pixel's samples are seeded by its index in scanline order (top row first), as the rays `vwrays`
// writes for the same view, so a traced pixel equals `vwrays | rtrace` on the same ray.
#pragma once
#include <vector>

#include "integrator/integrator.h"
#include "io/picture.h"
#include "spectrum/color_output.h"
#include "view/view.h"

namespace brume {

class ProgressMeter;
class Sequence;

struct PictureSettings {
    int xres = 512, yres = 512;     // -x -y: the largest resolution; one is reduced to fit the view's aspect
    double pixelAspect = 1;         // -pa: height over width of a pixel; 0 keeps -x and -y as given
    double jitter = 0.67;           // -pj: the fraction of a pixel over which its sample point is spread
    double aperture = 0;            // -pd: lens diameter in world units, focused at the length of -vd
    int sampleSpacing = 4;          // -ps: pixels between the samples of the first pass
    double sampleThreshold = 0.05;  // -pt: relative difference between samples above which pixels are traced
    bool irradiance = false;        // -i: irradiance at the surfaces seen, not their radiance
    bool drawSources = true;        // draw sources narrower than -ps pixels (Radiance's rule: with -dv+ and no -pd)
    bool depth = false;             // keep each pixel's distance (-z)
    ColorOutput color;              // -pRGB, -pXYZ, -pc: what the picture's three channels hold
};

// Values of light per pixel in the channels of the sampling in effect (RGB, or bands), rows from the top.
struct PixelSpectra {
    int width = 0, height = 0, channels = 3;
    std::vector<float> values;

    float* at(int x, int y) { return &values[size_t(channels) * (size_t(y) * width + x)]; }
    const float* at(int x, int y) const { return &values[size_t(channels) * (size_t(y) * width + x)]; }
};

struct RenderedPicture {
    Picture picture;           // resolution after fitting, pixel aspect, pixels as `color` asks (no header)
    std::vector<float> depth;  // distance to what each pixel sees (top row first), when asked
    PixelSpectra spectra;      // each pixel's bands, when the sampling has more than 3
};

// The resolution and pixel aspect `settings` give for `view` (Radiance's normaspect).
void fitResolution(const View& view, PictureSettings& settings);

// Renders a valid `view` at the scene's instant `time`, its pixels traced by the sequence's passes (records go
// to its -af file when the caller is done: Sequence::render);
// `settings` must have been fitted. Progress counts pixels. Light sources too small for the sampling are
// drawn in by their coverage of each pixel (small_sources.h).
RenderedPicture renderPicture(Sequence& sequence, const View& view, double time, const PictureSettings& settings,
                              ProgressMeter* progress = nullptr);

}  // namespace brume
