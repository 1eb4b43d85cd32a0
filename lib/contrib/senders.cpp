#include "contrib/senders.h"

#include <cctype>
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/polygon.h"
#include "sampling/random.h"
#include "sampling/warp.h"
#include "util/error.h"

namespace brume {

namespace {

constexpr int kTregenzaRows = 7;
constexpr int kTregenzaPerRow[kTregenzaRows] = {30, 30, 24, 24, 18, 12, 6};

// Reinhart's rows at MF subdivisions: 7 MF rows of patches from the horizon up, then the cap.
int reinhartRows(int mf) { return kTregenzaRows * mf + 1; }
int reinhartPerRow(int row, int mf) { return row >= reinhartRows(mf) - 1 ? 1 : mf * kTregenzaPerRow[row / mf]; }

const KlemsBasis* klemsBasis(const std::string& h) {
    char basis = klemsBasisOf(h);
    return KlemsBasis::standard(basis == 'f' ? "LBNL/Klems Full" : basis == 'h' ? "LBNL/Klems Half" : "LBNL/Klems Quarter");
}

}  // namespace

Sender::Surface Sender::surfaceOf(const FluxSurface& s) {
    Surface surface{s.normal, s.area, nullptr, {}, dvec3(0)};
    const std::vector<double>& a = s.arguments;
    if (s.type == "ring") {
        surface.centre = dvec3(a[0], a[1], a[2]);
        surface.inner = std::min(a[6], a[7]);
        return surface;
    }
    std::vector<dvec3> vertices;
    for (size_t i = 0; i + 2 < a.size(); i += 3) vertices.emplace_back(a[i], a[i + 1], a[i + 2]);
    std::string why;
    std::optional<Polygon> polygon = makePolygon(vertices, why);
    if (polygon) polygon->triangles = triangulate(*polygon);
    if (!polygon || polygon->triangles.empty())
        throw Error(s.at, "cannot sample sender polygon '" + s.name + "'" + (why.empty() ? "" : ": " + why));
    surface.polygon = std::make_unique<Polygon>(std::move(*polygon));
    surface.points = PolygonPoints(*surface.polygon);
    return surface;
}

Sender::Sender(const std::string& path) {
    FluxSettings settings;
    std::string modifier;
    for (const FluxSurface& s : readFluxSurfaces(path, "sender")) {
        if (s.source) throw Error(s.at, "cannot use source '" + s.name + "' as a sender");
        for (const auto& [at, words] : s.settings) applyFluxSettings(words, settings, at);
        if (!modifier.empty() && s.modifier != modifier) warn(s.at.str() + ": multiple modifiers in sender");
        modifier = s.modifier;
        normal_ += s.area * s.normal;
        surfaces_.push_back(surfaceOf(s));
    }
    if (surfaces_.empty()) throw Error(path + ": no sender surface (polygons or rings)");
    if (!settings.output.empty()) warn(path + ": ignoring output file in sender ('" + settings.output + "')");
    if (settings.hemisphere.empty()) throw Error(path + ": missing sender sampling type (h=)");
    setFrame(settings, path);
    setBasis(settings, path);
}

void Sender::setFrame(const FluxSettings& settings, const std::string& path) {
    if (!(glm::length(normal_) > 0)) throw Error(path + ": undefined normal for sender sampling");
    normal_ = glm::normalize(normal_);
    dvec3 across = glm::cross(upOf(settings, normal_), normal_);
    if (!(glm::length(across) > 1e-12)) throw Error(path + ": up vector coincides with sender normal");
    u_ = glm::normalize(across);
    v_ = glm::cross(normal_, u_);
    if (settings.sign == '-') u_ = -u_;
}

void Sender::setBasis(const FluxSettings& settings, const std::string& path) {
    const std::string& h = settings.hemisphere;
    char kind = char(std::tolower(static_cast<unsigned char>(h[0])));
    if (kind == 'u' || kind == '1') {
        kind_ = 'u';
    } else if (kind == 'r' || kind == 't') {
        kind_ = 'r';
        subdivisions_ = settings.size;
        bins_ = 0;
        for (int row = 0; row < reinhartRows(subdivisions_); ++row) bins_ += reinhartPerRow(row, subdivisions_);
    } else if (klemsBasisOf(h)) {
        kind_ = 'k';
        klems_ = klemsBasis(h);
        bins_ = klems_->size();
    } else {
        throw Error(path + ": sender sampling h=" + h + " is not supported (Brume has u, r, t and kf, kh, kq)");
    }
}

// In the basis's frame the bins' directions point out of the side the normal faces; rays go the other way.
dvec3 Sender::direction(int bin, double u, double v) const {
    if (kind_ == 'u') {
        double x, y;
        concentricDisk(u, v, x, y);
        return glm::normalize(local(dvec3(x, y, -std::sqrt(std::max(0.0, 1 - x * x - y * y)))));
    }
    if (kind_ == 'k') return glm::normalize(-local(klems_->direction(bin, u, v)));
    int row = 0, column = bin, rows = reinhartRows(subdivisions_);
    for (; column >= reinhartPerRow(row, subdivisions_); ++row) column -= reinhartPerRow(row, subdivisions_);
    if (row == rows - 1) u *= u;  // the cap: fewer rays crowd the zenith
    double altitude = (row + u) * (M_PI / 2) / (rows - 0.5);
    double azimuth = 2 * M_PI * (column + v - 0.5) / reinhartPerRow(row, subdivisions_);
    dvec3 d(std::sin(azimuth) * std::cos(altitude), -std::cos(azimuth) * std::cos(altitude), std::sin(altitude));
    return glm::normalize(-local(d));
}

dvec3 Sender::origin(const dvec3& dir, double u, double v) const {
    const Surface* s = &surfaces_.front();
    if (surfaces_.size() > 1) {
        double total = 0;
        for (const Surface& t : surfaces_) total += std::max(0.0, -glm::dot(t.normal, dir)) * t.area;
        if (!(total > 0)) throw Error("a sender direction is behind all its surfaces");
        double pick = u * total;
        for (const Surface& t : surfaces_) {
            double share = std::max(0.0, -glm::dot(t.normal, dir)) * t.area;
            if (!(share > 0)) continue;
            s = &t;
            u = std::min(pick / share, 1 - 0x1p-53);
            if (pick < share) break;
            pick -= share;
        }
    }
    if (s->polygon) return s->points.at(u, v);
    double radius = std::sqrt(u * s->area / M_PI + s->inner * s->inner), angle = 2 * M_PI * v;
    Frame frame(s->normal);
    return s->centre + radius * (std::cos(angle) * frame.s + std::sin(angle) * frame.t);
}

std::array<double, 6> Sender::ray(int bin, uint32_t index, uint64_t seed) const {
    uint64_t binSeed = mixBits(seed ^ (uint64_t(uint32_t(bin)) * 0x9e3779b97f4a7c15ULL));
    double u, v;
    sobol2D(index, binSeed, u, v);
    dvec3 dir = direction(bin, u, v);
    Random random(binSeed, index);
    double a = random.uniform(), b = random.uniform();
    dvec3 org = origin(dir, a, b);
    return {org.x, org.y, org.z, dir.x, dir.y, dir.z};
}

}  // namespace brume
