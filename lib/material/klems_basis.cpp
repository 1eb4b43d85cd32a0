#include "material/klems_basis.h"

#include <cmath>

namespace brume {

namespace {

constexpr double kDegree = M_PI / 180;

std::vector<KlemsBasis::Ring> ringsFrom(const std::vector<double>& bounds, const std::vector<int>& phis) {
    std::vector<KlemsBasis::Ring> rings;
    for (size_t i = 0; i < phis.size(); ++i) rings.push_back({bounds[i], bounds[i + 1], phis[i]});
    return rings;
}

}  // namespace

KlemsBasis::KlemsBasis(std::string name, std::vector<Ring> rings) : name_(std::move(name)), rings_(std::move(rings)) {
    for (const Ring& r : rings_) {
        double c0 = std::cos(r.lowerTheta * kDegree), c1 = std::cos(r.upperTheta * kDegree);
        for (int k = 0; k < r.phis; ++k) ohm_.push_back(M_PI * (c0 * c0 - c1 * c1) / r.phis);
        cosUpper_.push_back(c1);
        size_ += r.phis;
    }
}

const KlemsBasis* KlemsBasis::standard(const std::string& name) {
    static const KlemsBasis full("LBNL/Klems Full", ringsFrom({0, 5, 15, 25, 35, 45, 55, 65, 75, 90},
                                                              {1, 8, 16, 20, 24, 24, 24, 16, 12}));
    static const KlemsBasis half("LBNL/Klems Half",
                                 ringsFrom({0, 6.5, 19.5, 32.5, 45.5, 58.5, 71.5, 90}, {1, 8, 12, 16, 20, 12, 8}));
    static const KlemsBasis quarter("LBNL/Klems Quarter", ringsFrom({0, 9, 27, 45, 63, 90}, {1, 8, 12, 12, 8}));
    // WINDOW writes the names in this case; Radiance compares them ignoring case.
    auto same = [&](const std::string& a) {
        return a.size() == name.size() &&
               std::equal(a.begin(), a.end(), name.begin(), [](char x, char y) { return std::tolower(x) == std::tolower(y); });
    };
    for (const KlemsBasis* b : {&full, &half, &quarter})
        if (same(b->name())) return b;
    return nullptr;
}

int KlemsBasis::index(const dvec3& d) const {
    if (d.z < 0 || d.z > 1.00001) return -1;
    int first = 0;
    for (size_t r = 0; r < rings_.size(); ++r) {
        // θ < upper bound; a direction on a boundary belongs to the outer ring.
        if (d.z > cosUpper_[r]) {
            int phis = rings_[r].phis;
            if (phis == 1) return first;
            double phi = std::atan2(d.y, d.x) / kDegree;
            if (phi < 0) phi += 360;
            int k = int(phi / 360 * phis + 0.5);
            return first + (k >= phis ? 0 : k);
        }
        first += rings_[r].phis;
    }
    return -1;
}

int KlemsBasis::ring(int p, int& within) const {
    int i = 0;
    for (; p >= rings_[size_t(i)].phis; ++i) p -= rings_[size_t(i)].phis;
    within = p;
    return i;
}

dvec3 KlemsBasis::direction(int p, double u, double v) const {
    int k;
    const Ring& r = rings_[size_t(ring(p, k))];
    double c0 = std::cos(r.lowerTheta * kDegree), c1 = std::cos(r.upperTheta * kDegree);
    double cosTheta = std::sqrt((1 - u) * c0 * c0 + u * c1 * c1);
    double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
    double phi = 2 * M_PI * (k + v - 0.5) / r.phis;
    return {std::cos(phi) * sinTheta, std::sin(phi) * sinTheta, cosTheta};
}

int KlemsSide::index(const KlemsBasis& b, const dvec3& d) const {
    if ((d.z > 0) != front) return -1;
    double s = incident ? -1 : 1;
    return b.index({s * d.x, s * d.y, std::abs(d.z)});
}

dvec3 KlemsSide::direction(const KlemsBasis& b, int p, double u, double v) const {
    dvec3 d = b.direction(p, u, v);
    double s = incident ? -1 : 1;
    return {s * d.x, s * d.y, front ? d.z : -d.z};
}

}  // namespace brume
