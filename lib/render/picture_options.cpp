#include "render/picture_options.h"

#include "io/picture.h"
#include "util/error.h"

namespace brume {

void addPictureOptions(OptionTable& t, PictureSettings& p) {
    addIntOption(t, "-x", p.xres, "x resolution");
    addIntOption(t, "-y", p.yres, "y resolution");
    addRealOption(t, "-pa", p.pixelAspect, "pixel aspect ratio (height/width; 0: keep -x and -y)");
    addRealOption(t, "-pj", p.jitter, "pixel jitter");
    addRealOption(t, "-pd", p.aperture, "pixel depth of field: lens diameter, focused at the length of -vd");
    addIntOption(t, "-ps", p.sampleSpacing, "pixel sample spacing of the first pass");
    addRealOption(t, "-pt", p.sampleThreshold, "pixel threshold: relative difference traced between samples");
    t.add("-pm", 1, "pixel motion blur (only 0)", [](const auto& a) {
        if (toReal("-pm", a[0]) != 0) throw Error("motion blur (-pm) is not supported by Brume yet");
    }, [] { return std::string("0.000000"); });
}

void fitPictureResolution(const View& view, PictureSettings& p) {
    fitResolution(view, p);
    if (p.xres <= 0 || p.yres <= 0 || double(p.xres) * p.yres > kMaxPicturePixels)
        throw Error("bad resolution " + std::to_string(p.xres) + "x" + std::to_string(p.yres) + " (at most " +
                    std::to_string(long(kMaxPicturePixels)) + " pixels)");
}

}  // namespace brume
