#include "render/camera_path.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "util/error.h"

namespace brume {

namespace {

// Cosine of the largest turn between keys that has one shortest way (keys must not face opposite ways).
constexpr double kMostOpposite = -0.9999;

// Along the great circle from unit a to unit b (not opposite); linear where they are parallel within round-off.
dvec3 slerp(const dvec3& a, const dvec3& b, double t) {
    double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
    if (angle < 1e-9) return glm::normalize(a + t * (b - a));
    return (std::sin((1 - t) * angle) * a + std::sin(t * angle) * b) / std::sin(angle);
}

CameraKey parseKey(const std::string& line, const SourceLocation& where, const dvec3& defaultUp) {
    std::istringstream in(line);
    std::vector<double> v;
    std::string word;
    while (in >> word) {
        char* end;
        double x = std::strtod(word.c_str(), &end);
        if (*end || !std::isfinite(x)) throw Error(where, "'" + word + "' is not a number");
        v.push_back(x);
    }
    if (v.size() != 7 && v.size() != 10)
        throw Error(where, "expected time, position, direction and an optional up vector (7 or 10 numbers), got " +
                               std::to_string(v.size()));
    CameraKey k{v[0], {v[1], v[2], v[3]}, {v[4], v[5], v[6]}, v.size() == 10 ? dvec3(v[7], v[8], v[9]) : defaultUp};
    if (!(glm::length(k.direction) > 0)) throw Error(where, "zero view direction");
    if (!(glm::length(k.up) > 0)) throw Error(where, "zero view up vector");
    return k;
}

}  // namespace

CameraPath CameraPath::read(const std::string& path, const dvec3& defaultUp) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot open camera path");
    return parse(in, path, defaultUp);
}

CameraPath CameraPath::parse(std::istream& in, const std::string& path, const dvec3& defaultUp) {
    CameraPath p;
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        SourceLocation where{path, n};
        CameraKey k = parseKey(line, where, defaultUp);
        if (!p.keys_.empty() && !(k.time > p.keys_.back().time))
            throw Error(where, "times must increase from line to line");
        auto opposite = [](const dvec3& a, const dvec3& b) {
            return glm::dot(glm::normalize(a), glm::normalize(b)) < kMostOpposite;
        };
        if (!p.keys_.empty() && (opposite(k.direction, p.keys_.back().direction) || opposite(k.up, p.keys_.back().up)))
            throw Error(where, "the camera turns half round from the previous key (which way is ambiguous): add a key between");
        p.keys_.push_back(k);
    }
    if (p.keys_.empty()) throw Error(path + ": no camera keys");
    return p;
}

View CameraPath::at(double time, const View& base) const {
    auto after = std::upper_bound(keys_.begin(), keys_.end(), time,
                                  [](double t, const CameraKey& k) { return t < k.time; });
    const CameraKey& b = after == keys_.end() ? keys_.back() : *after;
    const CameraKey& a = after == keys_.begin() ? keys_.front() : *(after - 1);
    double t = b.time > a.time ? std::clamp((time - a.time) / (b.time - a.time), 0.0, 1.0) : 0.0;
    View v = base;
    v.vp = a.position + t * (b.position - a.position);
    double la = glm::length(a.direction), lb = glm::length(b.direction);
    v.vd = slerp(a.direction / la, b.direction / lb, t) * (la + t * (lb - la));
    v.vu = slerp(glm::normalize(a.up), glm::normalize(b.up), t);
    return v;
}

std::vector<TimedView> CameraPath::frames(const View& base, double fps) const {
    std::vector<TimedView> out;
    if (fps <= 0) {
        for (const CameraKey& k : keys_) out.push_back({k.time, at(k.time, base)});
        return out;
    }
    double t0 = keys_.front().time, span = keys_.back().time - t0;
    // Frames by index, not by accumulating 1/fps, so the last one lands on the last key when it should.
    long n = long(std::floor(span * fps + 1e-9));
    for (long i = 0; i <= n; ++i) out.push_back({t0 + i / fps, at(t0 + i / fps, base)});
    return out;
}

}  // namespace brume
