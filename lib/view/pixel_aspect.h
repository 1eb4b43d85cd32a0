// Fitting an image's resolution to its view, as Radiance's normaspect does for rpict, rtrace and vwrays:
// pixels of a chosen shape (-pa, height over width) cover the view's image with at most -x by -y of them.
#pragma once

namespace brume {

// With pixelAspect > 0 (Radiance's FTINY and below count as 0), shrinks xres or yres, rounding to the
// nearest integer, so that xres by yres pixels of that shape match viewAspect (View::aspect()); with 0,
// keeps xres and yres and sets pixelAspect to the shape they give.
void normalizeResolution(double viewAspect, double& pixelAspect, int& xres, int& yres);

}  // namespace brume
