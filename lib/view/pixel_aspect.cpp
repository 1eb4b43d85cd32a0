#include "view/pixel_aspect.h"

namespace brume {

void normalizeResolution(double viewAspect, double& pixelAspect, int& xres, int& yres) {
    if (pixelAspect <= 1e-6) {
        pixelAspect = viewAspect * xres / yres;
        return;
    }
    // The operations in Radiance's order, so that halves round the same way.
    if (viewAspect * xres > pixelAspect * yres) xres = int(yres / viewAspect * pixelAspect + .5);
    else yres = int(xres * viewAspect / pixelAspect + .5);
}

}  // namespace brume
