// Light sources too small in a picture for its pixel sampling to find them (Radiance's srcdraw): a distant
// lamp, the sun in a wide view. A pixel's one ray would either miss such a source or see it as if it
// filled the pixel; instead each pixel it covers gets the source's radiance weighted by the part of the
// pixel covered. Radiance's rpict does this for sources narrower than -ps pixels; so does Brume's.
#pragma once
#include <vector>

#include "integrator/integrator.h"
#include "render/picture_renderer.h"
#include "view/view.h"

namespace brume {

// Draws the sources of the integrator's scene narrower than `widthLimit` pixels into `picture` (at the scene's
// instant `time`), and their distance into `depth` where nearer, if given. A source is drawn where a ray
// through the middle of its part of a pixel reaches it unobstructed. Illum sources (windows) are not drawn.
void drawSmallSources(const Integrator& integrator, double time, const View& view, double widthLimit,
                      PixelSpectra& picture, std::vector<float>* depth);

}  // namespace brume
