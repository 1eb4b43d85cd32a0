#include "view/view.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "util/error.h"

namespace brume {

namespace {

// Radiance's tolerance for sizes and clipping distances (FTINY in double-precision builds).
constexpr double kTiny = 1e-6;
constexpr double kDegree = M_PI / 180;

// The image-plane vectors of a view: hvec to the right, vvec up, each scaled as Radiance's setview scales
// them, and the squared scales hn2, vn2.
struct Frame {
    dvec3 dir, hvec, vvec;
    double hn2 = 0, vn2 = 0;
};

// Computes the frame, or returns the reason there is none (Radiance's setview, its checks in its order).
std::string makeFrame(const View& v, Frame& f) {
    const std::string illHoriz = "illegal horizontal view size", illVert = "illegal vertical view size";
    if (v.vo < -kTiny || v.va < -kTiny || (v.va > kTiny && v.va <= v.vo)) return "illegal fore/aft clipping plane";
    double dlen = glm::length(v.vd);
    if (!(dlen > 0)) return "zero view direction";
    double ulen = glm::length(v.vu);
    if (!(ulen > 0)) return "zero view up vector";
    f.dir = v.vd / dlen;
    dvec3 up = v.vu / ulen;
    dvec3 h = glm::cross(f.dir, up);
    double hlen = glm::length(h);
    // Radiance refuses only an exactly zero cross product; an up within round-off of the view direction
    // gives no meaningful frame either, so Brume refuses that too.
    if (hlen <= 1e-12) return "view up parallel to view direction";
    f.hvec = h / hlen;
    f.vvec = glm::cross(f.hvec, f.dir);
    if (v.vh <= kTiny) return illHoriz;
    if (v.vv <= kTiny) return illVert;
    double hn = 0, vn = 0;
    switch (v.type) {
    case kParallel:
        hn = v.vh, vn = v.vv;
        break;
    case kPerspective:
        if (v.vh >= 180 - kTiny) return illHoriz;
        if (v.vv >= 180 - kTiny) return illVert;
        hn = 2 * std::tan(v.vh * kDegree / 2), vn = 2 * std::tan(v.vv * kDegree / 2);
        break;
    case kCylindrical:
        if (v.vh > 360 + kTiny) return illHoriz;
        if (v.vv >= 180 - kTiny) return illVert;
        hn = v.vh * kDegree, vn = 2 * std::tan(v.vv * kDegree / 2);
        break;
    case kAngular:
        if (v.vh > 360 + kTiny) return illHoriz;
        if (v.vv > 360 + kTiny) return illVert;
        hn = v.vh * kDegree, vn = v.vv * kDegree;
        break;
    case kHemispherical:
        if (v.vh > 180 + kTiny) return illHoriz;
        if (v.vv > 180 + kTiny) return illVert;
        hn = 2 * std::sin(v.vh * kDegree / 2), vn = 2 * std::sin(v.vv * kDegree / 2);
        break;
    case kPlanisphere:
        if (v.vh >= 360 - kTiny) return illHoriz;
        if (v.vv >= 360 - kTiny) return illVert;
        // 2 tan(vh/4): the stereographic radius of the edge, vh/2 off axis
        hn = 2 * std::sin(v.vh * kDegree / 2) / (1 + std::cos(v.vh * kDegree / 2));
        vn = 2 * std::sin(v.vv * kDegree / 2) / (1 + std::cos(v.vv * kDegree / 2));
        break;
    default:
        return "unknown view type";
    }
    if (v.type != kAngular && v.type != kPlanisphere) {
        if (v.type != kCylindrical) f.hvec *= hn;
        f.vvec *= vn;
    }
    f.hn2 = hn * hn, f.vn2 = vn * vn;
    return {};
}

std::optional<double> number(const std::string& s) {
    if (s.empty()) return std::nullopt;
    char* end;
    double v = std::strtod(s.c_str(), &end);
    if (*end || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::string format(const char* fmt, double a) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, a);
    return buf;
}

}  // namespace

std::string View::problem() const {
    Frame f;
    return makeFrame(*this, f);
}

void View::validate() const {
    if (std::string p = problem(); !p.empty()) throw Error(p);
}

double View::aspect() const {
    Frame f;
    if (std::string p = makeFrame(*this, f); !p.empty()) throw Error(p);
    return std::sqrt(f.vn2 / f.hn2);
}

std::optional<glm::dvec2> View::location(const dvec3& p) const {
    Frame f;
    if (!makeFrame(*this, f).empty()) return std::nullopt;
    dvec3 d = p - vp, h = glm::normalize(f.hvec), u = glm::normalize(f.vvec);
    double z = glm::dot(d, f.dir), a = glm::dot(d, h), b = glm::dot(d, u);
    double hn = std::sqrt(f.hn2), vn = std::sqrt(f.vn2);
    double x, y;  // centred on the view axis, in image widths and heights
    switch (type) {
    case kParallel:
        x = a / hn, y = b / vn;
        break;
    case kPerspective:
        if (z <= 0) return std::nullopt;
        x = a / (z * hn), y = b / (z * vn);
        break;
    case kCylindrical: {
        double across = std::hypot(z, a);
        if (!(across > 0)) return std::nullopt;
        x = std::atan2(a, z) / (vh * kDegree), y = b / (across * vn);
        break;
    }
    default: {  // the fisheyes, by the unit direction toward p
        double len = glm::length(d);
        if (!(len > 0)) return std::nullopt;
        z /= len, a /= len, b /= len;
        if (type == kHemispherical) {
            if (z < 0) return std::nullopt;
            x = a / hn, y = b / vn;
        } else if (type == kAngular) {
            double angle = std::acos(std::clamp(z, -1.0, 1.0)), s = std::hypot(a, b);
            if (angle > M_PI - kTiny) return std::nullopt;
            double k = s > kTiny ? angle / (M_PI * s) : 1 / M_PI;  // angle/π along the direction off axis
            x = a * k * 180 / vh, y = b * k * 180 / vv;
        } else {  // planisphere
            if (z <= -1 + kTiny) return std::nullopt;
            x = a / ((1 + z) * hn), y = b / ((1 + z) * vn);
        }
    }
    }
    return glm::dvec2(x + 0.5 - vs, y + 0.5 - vl);
}

std::optional<ViewRay> View::ray(double x, double y) const {
    Frame f;
    if (!makeFrame(*this, f).empty()) return std::nullopt;
    x += vs - 0.5;
    y += vl - 0.5;
    double aft = va > kTiny ? va - vo : std::numeric_limits<double>::infinity();
    ViewRay r;
    // For the fisheyes below, z is the cosine of the angle off the view direction and (x, y) the
    // components along hvec and vvec, scaled so that the direction comes out unit length.
    auto along = [&](double z, double hx, double vy) { return z * f.dir + hx * f.hvec + vy * f.vvec; };
    switch (type) {
    case kParallel:
        r.org = vp + vo * f.dir + x * f.hvec + y * f.vvec;
        r.dir = f.dir;
        r.tmax = aft;
        return r;
    case kPerspective: {
        dvec3 d = along(1, x, y);  // reaches the image plane at distance 1
        r.org = vp + vo * d;       // so -vo and -va are planes, not spheres
        double len = glm::length(d);
        r.dir = d / len;
        r.tmax = aft * len;
        return r;
    }
    case kHemispherical: {
        double z = 1 - x * x * f.hn2 - y * y * f.vn2;
        if (z < 0) return std::nullopt;
        r.dir = along(std::sqrt(z), x, y);
        break;
    }
    case kCylindrical: {
        double a = x * vh * kDegree;
        dvec3 d = along(std::cos(a), std::sin(a), y);
        r.org = vp + vo * d;  // -vo and -va are cylinders about the up axis
        double len = glm::length(d);
        r.dir = d / len;
        r.tmax = aft * len;
        return r;
    }
    case kAngular: {
        x *= vh / 180, y *= vv / 180;
        double rho = std::sqrt(x * x + y * y);  // the angle off the view direction, in units of pi
        if (rho > 1) return std::nullopt;
        double z = std::cos(M_PI * rho);
        double s = rho <= kTiny ? M_PI : std::sqrt(1 - z * z) / rho;
        r.dir = along(z, x * s, y * s);
        break;
    }
    case kPlanisphere: {
        x *= std::sqrt(f.hn2), y *= std::sqrt(f.vn2);
        double d2 = x * x + y * y;  // tan^2 of half the angle off the view direction
        double z = (1 - d2) / (1 + d2);
        r.dir = along(z, x * (1 + z), y * (1 + z));
        break;
    }
    default:
        return std::nullopt;
    }
    // The fisheyes: clipping distances are spheres about the view point.
    r.org = vp + vo * r.dir;
    r.tmax = aft;
    return r;
}

std::string View::options() const {
    std::string s = "-vt";
    s += type;
    s += " -vp" + format(" %.7g", vp.x) + format(" %.7g", vp.y) + format(" %.7g", vp.z);
    s += " -vd" + format(" %.7g", vd.x) + format(" %.7g", vd.y) + format(" %.7g", vd.z);
    s += " -vu" + format(" %.5g", vu.x) + format(" %.5g", vu.y) + format(" %.5g", vu.z);
    s += " -vh" + format(" %.5g", vh) + " -vv" + format(" %.5g", vv);
    s += " -vo" + format(" %.5g", vo) + " -va" + format(" %.5g", va);
    s += " -vs" + format(" %.5g", vs) + " -vl" + format(" %.5g", vl);
    return s;
}

size_t parseViewOption(View& view, std::span<const std::string> args) {
    if (args.empty()) return 0;
    const std::string& a = args[0];
    if (a.size() < 3 || a[0] != '-' || a[1] != 'v') return 0;
    if (a[2] == 't') {
        if (a.size() != 4) return 0;
        view.type = a[3];
        return 1;
    }
    if (a.size() != 3) return 0;
    auto values = [&](size_t n) {
        std::vector<double> v;
        for (size_t i = 1; i <= n; i++) {
            auto x = i < args.size() ? number(args[i]) : std::nullopt;
            if (!x) throw Error(a + (n == 1 ? " needs a number" : " needs " + std::to_string(n) + " numbers"));
            v.push_back(*x);
        }
        return v;
    };
    auto vec = [&](dvec3& out) {
        auto v = values(3);
        out = {v[0], v[1], v[2]};
        return size_t(4);
    };
    auto one = [&](double& out) {
        out = values(1)[0];
        return size_t(2);
    };
    switch (a[2]) {
    case 'p': return vec(view.vp);
    case 'd': return vec(view.vd);
    case 'u': return vec(view.vu);
    case 'h': return one(view.vh);
    case 'v': return one(view.vv);
    case 'o': return one(view.vo);
    case 'a': return one(view.va);
    case 's': return one(view.vs);
    case 'l': return one(view.vl);
    }
    return 0;
}

int parseViewString(View& view, std::string_view text) {
    std::vector<std::string> words;
    for (size_t i = 0; i < text.size();) {
        while (i < text.size() && std::isspace((unsigned char)text[i])) i++;
        size_t start = i;
        while (i < text.size() && !std::isspace((unsigned char)text[i])) i++;
        if (i > start) words.emplace_back(text.substr(start, i - start));
    }
    int read = 0;
    for (size_t i = 0; i < words.size();) {
        std::span<const std::string> rest(words.begin() + i, words.end());
        View trial = view;
        size_t used = 0;
        try {
            used = parseViewOption(trial, rest);
        } catch (const Error&) {
            used = 0;  // a malformed option is skipped, as Radiance skips it
        }
        if (used == 0) {
            i++;
            continue;
        }
        view = trial;
        read++;
        i += used;
    }
    return read;
}

bool isViewLine(std::string_view line) {
    size_t end = 0;
    while (end < line.size() && !std::isspace((unsigned char)line[end])) end++;
    std::string_view word = line.substr(0, end);
    if (size_t slash = word.rfind('/'); slash != std::string_view::npos) word = word.substr(slash + 1);
    const std::string& self = programName();
    if (!self.empty() && word.substr(0, self.size()) == self) return true;
    for (std::string_view name : {"VIEW=", "rpict", "rvu", "rpiece", "rxpiece", "pinterp", "rview"})
        if (word.substr(0, name.size()) == name) return true;
    return false;
}

}  // namespace brume
