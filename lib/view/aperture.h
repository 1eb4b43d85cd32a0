// Depth of field (-pd): a lens of the given diameter at the view point, focused at the distance given by
// the length of -vd. Radiance's jitteraperture, shared by rpict and vwrays.
#pragma once
#include "view/view.h"

namespace brume {

// Moves `ray` (made by view.ray()) to start at a point of the aperture disc, spread over the image
// plane's right and up axes around the view point, and to aim at the point its original direction reached
// at the focal distance: on the focal plane for perspective and parallel views, on the focal sphere for
// the others, whose origin is also moved along -vd by up to ±π/16 of the diameter, as Radiance does.
// u1, u2 pick the point on the disc (concentric map), u3 the shift along -vd; all uniform in [0, 1).
// -vo moves the new origin forward again; ray.tmax is kept. Does nothing when diameter is at most 1e-6.
// Returns false when the ray has no direction left (its origin landed on its focal point), a ray to drop.
bool jitterAperture(const View& view, ViewRay& ray, double diameter, double u1, double u2, double u3);

}  // namespace brume
