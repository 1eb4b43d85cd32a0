#include "contrib/flux_surfaces.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace brume {

namespace {

using glm::dvec3;

// u=: an axis (X, +Y, -Z) or three numbers "x,y,z".
std::optional<dvec3> direction(const std::string& text) {
    double sign = 1;
    size_t i = 0;
    for (; i < text.size() && (text[i] == '+' || text[i] == '-'); ++i)
        if (text[i] == '-') sign = -sign;
    std::string rest = text.substr(i);
    if (rest.size() == 1) {
        int axis = std::tolower(static_cast<unsigned char>(rest[0])) - 'x';
        if (axis < 0 || axis > 2) return std::nullopt;
        dvec3 d(0);
        d[axis] = sign;
        return d;
    }
    dvec3 d;
    char comma1, comma2, extra;
    std::istringstream in(rest);
    if (!(in >> d.x >> comma1 >> d.y >> comma2 >> d.z) || comma1 != ',' || comma2 != ',' || (in >> extra))
        return std::nullopt;
    if (!(glm::length(d) > 0) || !std::isfinite(glm::length(d))) return std::nullopt;
    return sign * glm::normalize(d);
}

}  // namespace

char klemsBasisOf(const std::string& h) {
    if (h.empty() || std::tolower(static_cast<unsigned char>(h[0])) != 'k') return 0;
    char c = h.size() == 1 ? 'f' : char(std::tolower(static_cast<unsigned char>(h[1])));
    return c == 'f' || c == '1' ? 'f' : c == 'h' || c == '2' ? 'h' : c == 'q' || c == '4' ? 'q' : 0;
}

glm::dvec3 upOf(const FluxSettings& s, const glm::dvec3& normal) {
    return s.up ? *s.up : std::abs(normal.z) < 0.7 ? dvec3(0, 0, 1) : dvec3(0, 1, 0);
}

void applyFluxSettings(const std::string& words, FluxSettings& s, const SourceLocation& where) {
    std::istringstream in(words);
    for (std::string w; in >> w;) {
        if (w.rfind("h=", 0) == 0 && w.size() > 2) {
            std::string h = w.substr(2);
            s.sign = h[0] == '-' ? '-' : '+';
            if (h[0] == '+' || h[0] == '-') h = h.substr(1);
            if (h.empty()) throw Error(where, "bad parameter h=" + w.substr(2));
            s.hemisphere = h;
            // The number after the type's letter (Reinhart's MF), as Radiance's atoi reads it.
            long n = 0;
            for (size_t k = 1; k < h.size() && std::isdigit(static_cast<unsigned char>(h[k])) && n <= kMaxSubdivisions; ++k)
                n = 10 * n + (h[k] - '0');
            if (n > kMaxSubdivisions)
                throw Error(where, "bad parameter h=" + w.substr(2) + ": more than " + std::to_string(kMaxSubdivisions) +
                                       " subdivisions");
            s.size = n > 0 ? int(n) : 1;
        } else if (w.rfind("u=", 0) == 0) {
            s.up = direction(w.substr(2));
            if (!s.up) throw Error(where, "bad up direction " + w);
        } else if (w.rfind("o=", 0) == 0 && w.size() > 2) {
            s.output = w.substr(2);
            if ((s.output[0] == '"' || s.output[0] == '\'') && s.output.size() > 1 && s.output.back() == s.output[0])
                s.output = s.output.substr(1, s.output.size() - 2);
        } else {
            throw Error(where, "bad parameter string: " + words);
        }
    }
}

namespace {

struct Shape {
    double area;
    dvec3 normal;
    bool source;
};

// A polygon's (its vertices' right-hand order), a ring's, or a source's (opposite its direction, over the
// solid angle of a cone of its angle); nullopt for other types.
std::optional<Shape> shapeOf(const std::string& type, const std::vector<double>& a, const std::string& name,
                             const SourceLocation& where) {
    auto bad = [&] { return Error(where, "bad argument count for surface element '" + name + "'"); };
    if (type == "polygon") {
        if (a.size() < 9 || a.size() % 3) throw bad();
        dvec3 n(0), first(a[0], a[1], a[2]), e1 = dvec3(a[3], a[4], a[5]) - first;
        for (size_t i = 2; i < a.size() / 3; ++i) {
            dvec3 e2 = dvec3(a[3 * i], a[3 * i + 1], a[3 * i + 2]) - first;
            n += glm::cross(e1, e2);
            e1 = e2;
        }
        double twice = glm::length(n);
        if (!(twice > 0)) return Shape{0, dvec3(0), false};
        return Shape{twice / 2, n / twice, false};
    }
    if (type == "ring") {
        if (a.size() != 8) throw bad();
        dvec3 n(a[3], a[4], a[5]);
        if (!(glm::length(n) > 0)) throw Error(where, "bad orientation for surface element '" + name + "'");
        double r0 = std::min(a[6], a[7]), r1 = std::max(a[6], a[7]);
        return Shape{M_PI * (r1 * r1 - r0 * r0), glm::normalize(n), false};
    }
    if (type == "source") {
        if (a.size() != 4) throw bad();
        dvec3 n(-a[0], -a[1], -a[2]);
        if (!(glm::length(n) > 0)) throw Error(where, "bad orientation for surface element '" + name + "'");
        double s = std::sin(M_PI / 360 * a[3]);
        return Shape{M_PI * s * s, glm::normalize(n), true};
    }
    return std::nullopt;
}

}  // namespace

std::vector<FluxSurface> readFluxSurfaces(const std::string& path, const std::string& role) {
    std::ifstream file(path);
    if (!file) throw Error(path + ": cannot open " + role + " file");
    std::vector<FluxSurface> out;
    std::vector<std::pair<SourceLocation, std::string>> settings;
    std::string line;
    int lineNo = 0;
    // Objects may span lines: words are read from the whole text, with their line numbers kept for
    // messages by reading line by line into one stream of (line, word) pairs.
    std::vector<std::pair<int, std::string>> words;
    while (std::getline(file, line)) {
        ++lineNo;
        size_t start = line.find_first_not_of(" \t\r");
        if (start != std::string::npos && line[start] == '!')
            throw Error(SourceLocation{path, lineNo}, "commands in " + role + " files are not supported");
        size_t hash = line.find('#');
        if (hash != std::string::npos) {
            std::string comment = line.substr(hash + 1);
            if (comment.rfind("@rfluxmtx", 0) == 0) {
                words.push_back({lineNo, "#@rfluxmtx"});
                words.push_back({lineNo, comment.substr(9)});
            }
            line = line.substr(0, hash);
        }
        std::istringstream in(line);
        for (std::string w; in >> w;) words.push_back({lineNo, w});
    }
    size_t i = 0;
    auto where = [&] { return SourceLocation{path, i < words.size() ? words[i].first : lineNo}; };
    auto next = [&](const char* what) -> std::string {
        if (i >= words.size()) throw Error(SourceLocation{path, lineNo}, std::string("missing ") + what);
        return words[i++].second;
    };
    while (i < words.size()) {
        if (words[i].second == "#@rfluxmtx") {
            SourceLocation at = where();
            ++i;
            settings.emplace_back(at, next("settings"));
            continue;
        }
        SourceLocation at = where();
        std::string modifier = next("modifier"), type = next("type"), name = next("name");
        if (type == "alias") {
            next("alias");
            continue;
        }
        // Its strings, integers and reals, each a count and that many words.
        auto group = [&]() {
            long n;
            try {
                n = std::stol(next("argument count"));
            } catch (const std::logic_error&) {
                throw Error(at, "bad argument count for '" + name + "'");
            }
            if (n < 0 || n > 100000) throw Error(at, "bad argument count for '" + name + "'");
            std::vector<std::string> out;
            for (long k = 0; k < n; ++k) out.push_back(next("argument"));
            return out;
        };
        group();  // strings: none a surface takes here
        group();  // integers
        std::vector<double> reals;
        for (const std::string& w : group()) {
            size_t used = 0;
            try {
                reals.push_back(std::stod(w, &used));
            } catch (const std::logic_error&) {
            }
            if (used != w.size()) throw Error(at, "bad real argument '" + w + "' of '" + name + "'");
        }
        std::optional<Shape> s = shapeOf(type, reals, name, at);
        if (!s) continue;
        if (!std::isfinite(s->area)) throw Error(at, "surface element '" + name + "' too large to measure");
        if (!(s->area > 0)) {
            warn(at.str() + ": zero area for surface '" + name + "'");
            continue;
        }
        out.push_back({modifier, type, name, at, std::move(reals), s->area, s->normal, s->source, std::move(settings)});
        settings.clear();
    }
    return out;
}

}  // namespace brume
