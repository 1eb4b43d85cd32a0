#include "geometry/transform.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdlib>
#include <optional>

namespace brume {

bool isTransformOption(std::string_view a) {
    if (a.size() == 2 && a[0] == '-') return a[1] == 't' || a[1] == 's' || a[1] == 'i';
    return a.size() == 3 && a[0] == '-' && (a[1] == 'r' || a[1] == 'm') && a[2] >= 'x' && a[2] <= 'z';
}

namespace {

std::optional<double> number(std::span<const std::string> args, size_t i) {
    if (i >= args.size() || args[i].empty()) return std::nullopt;
    char* end;
    double v = std::strtod(args[i].c_str(), &end);
    if (*end || !std::isfinite(v)) return std::nullopt;
    return v;
}

dvec3 axis(char c) { return dvec3(c == 'x', c == 'y', c == 'z'); }

// Counter-clockwise about the axis looking down it, the cosines and sines placed as Radiance's xf() places
// them: glm::rotate's general formula computes the diagonal as c + (1 - c), which can miss 1 by a bit and
// then shows in xform's 12-digit output.
glm::dmat4 rotation(char axisName, double radians) {
    int u = axisName == 'x' ? 1 : axisName == 'y' ? 2 : 0, v = (u + 1) % 3;  // the plane turned: u to v
    glm::dmat4 m(1.0);
    m[u][u] = m[v][v] = std::cos(radians);
    m[u][v] = std::sin(radians);
    m[v][u] = -m[u][v];
    return m;
}

// One transform option at args[i]: its matrix and scale, and how many arguments it takes; nullopt ends parsing.
struct Step {
    glm::dmat4 matrix{1.0};
    double scale = 1;
    size_t used = 1;
};

std::optional<Step> step(std::span<const std::string> args, size_t i) {
    const std::string& a = args[i];
    Step s;
    switch (a[1]) {
    case 't': {
        auto x = number(args, i + 1), y = number(args, i + 2), z = number(args, i + 3);
        if (!x || !y || !z) return std::nullopt;
        s.matrix[3] = glm::dvec4(*x, *y, *z, 1);
        s.used = 4;
        return s;
    }
    case 'r': {
        auto degrees = number(args, i + 1);
        if (!degrees) return std::nullopt;
        s.matrix = rotation(a[2], (M_PI / 180.) * *degrees);
        s.used = 2;
        return s;
    }
    case 's': {
        auto f = number(args, i + 1);
        if (!f || *f == 0) return std::nullopt;
        s.matrix = glm::scale(glm::dmat4(1.0), dvec3(*f));
        s.scale = *f;
        s.used = 2;
        return s;
    }
    case 'm':
        s.matrix = glm::scale(glm::dmat4(1.0), dvec3(1.0) - 2.0 * axis(a[2]));
        s.scale = -1;
        return s;
    }
    return std::nullopt;
}

}  // namespace

ParsedTransform parseTransform(std::span<const std::string> args) {
    ParsedTransform result;
    Transform group;  // the transforms since the last -i, applied `repeats` times
    long repeats = 1;
    auto flush = [&] {
        for (long k = 0; k < repeats; ++k) result.transform = result.transform.then(group);
        group = Transform{};
    };
    size_t i = 0;
    while (i < args.size() && isTransformOption(args[i])) {
        if (args[i][1] == 'i') {
            auto n = number(args, i + 1);
            if (!n || *n != std::floor(*n) || *n < 0 || *n > 1e6) break;
            flush();
            repeats = long(*n);
            i += 2;
            continue;
        }
        auto s = step(args, i);
        if (!s) break;
        group = group.then(Transform{s->matrix, s->scale});
        i += s->used;
    }
    flush();
    result.used = i;
    return result;
}

}  // namespace brume
