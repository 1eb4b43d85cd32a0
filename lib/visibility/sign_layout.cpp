#include "visibility/sign_layout.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "util/error.h"
#include "visibility/line_words.h"

namespace brume {

std::array<dvec3, 4> SignPlacement::corners() const {
    const dvec3 up = std::abs(front.z) > 0.99 ? dvec3(0, 1, 0) : dvec3(0, 0, 1);
    const dvec3 across = glm::normalize(glm::cross(up, front));  // across × along = front
    const dvec3 along = glm::cross(front, across);
    const dvec3 u = 0.5 * width * across, v = 0.5 * height * along;
    return {centre - u - v, centre + u - v, centre + u + v, centre - u + v};
}

std::vector<SignPlacement> readSignPlacements(std::istream& in, const std::string& file) {
    std::vector<SignPlacement> out;
    forEachWordLine(in, file, [&](const std::vector<std::string>& w, const std::string& where) {
        if (w.size() < 11 || w.size() > 12)
            throw Error(where + ": expected 'name x y z front_x front_y front_z width height emitting|reflecting "
                                "luminance|reflectance [C]'");
        SignPlacement s;
        s.name = w[0];
        s.where = where;
        const std::string of = "sign '" + w[0] + "': ";
        for (int k = 0; k < 3; ++k) {
            s.centre[k] = realWord(w[1 + size_t(k)], where, of + "centre");
            s.front[k] = realWord(w[4 + size_t(k)], where, of + "front");
        }
        if (!(glm::length(s.front) > 0)) throw Error(where + ": " + of + "its front has no direction");
        s.front = glm::normalize(s.front);
        s.width = realWord(w[7], where, of + "width"), s.height = realWord(w[8], where, of + "height");
        if (!(s.width > 0 && s.height > 0)) throw Error(where + ": " + of + "width and height must be > 0");
        if (w[9] != "emitting" && w[9] != "reflecting")
            throw Error(where + ": " + of + "kind '" + w[9] + "' is neither emitting nor reflecting");
        s.kind = w[9] == "emitting" ? SignKind::Emitting : SignKind::Reflecting;
        s.shows = realWord(w[10], where, of + (s.kind == SignKind::Emitting ? "luminance" : "reflectance"));
        if (s.kind == SignKind::Emitting && !(s.shows > 0)) throw Error(where + ": " + of + "luminance must be > 0");
        if (s.kind == SignKind::Reflecting && !(s.shows > 0 && s.shows <= 1))
            throw Error(where + ": " + of + "reflectance must be in (0, 1]");
        s.jinConstant = jinConstant(s.kind);
        if (w.size() == 12 && !((s.jinConstant = realWord(w[11], where, of + "Jin's C")) > 0))
            throw Error(where + ": " + of + "Jin's C must be > 0");
        for (const SignPlacement& e : out)
            if (e.name == s.name) throw Error(where + ": " + of + "listed twice (" + e.where + ")");
        out.push_back(s);
    });
    if (out.empty()) throw Error(file + ": no signs");
    return out;
}

}  // namespace brume
