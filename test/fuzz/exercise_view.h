// What the view fuzz target does with one input, shared with the corpus replay test: read it as view lines
// (a view file, -S input) and as a camera path, then make rays through the image and, for a path, frames.
// Errors (brume::Error) are fine; crashes are not, and a valid view giving a ray that is not finite (or a
// direction that is not unit length) makes this return false.
#pragma once
#include <cmath>
#include <sstream>
#include <string>
#include <string_view>

#include <glm/geometric.hpp>

#include "render/camera_path.h"
#include "util/error.h"
#include "view/pixel_aspect.h"
#include "view/view.h"

namespace brume {

inline bool raysAreFinite(const View& v) {
    if (!v.problem().empty()) return true;
    auto finite = [](const dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
    for (double x : {0.0, 0.013, 0.5, 0.77, 1.0})
        for (double y : {0.0, 0.31, 0.5, 1.0})
            if (auto r = v.ray(x, y); r && (!finite(r->org) || !finite(r->dir) || std::abs(glm::length(r->dir) - 1) > 1e-6))
                return false;
    double pixelAspect = 1;
    int xres = 512, yres = 512;
    normalizeResolution(v.aspect(), pixelAspect, xres, yres);
    return xres >= 0 && yres >= 0;
}

inline bool exerciseViewText(std::string_view text) {
    View view;
    std::istringstream lines{std::string(text)};
    for (std::string line; std::getline(lines, line);) {
        if (!isViewLine(line)) continue;
        parseViewString(view, line);
        if (!raysAreFinite(view)) return false;
    }
    try {
        std::istringstream in{std::string(text)};
        CameraPath path = CameraPath::parse(in, "fuzz", {0, 0, 1});
        for (const TimedView& f : path.frames(View{}, 7))
            if (!raysAreFinite(f.view)) return false;
    } catch (const Error&) {
    }
    return true;
}

}  // namespace brume
