#include "medium/data_coverage.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "util/error.h"

namespace brume {

namespace {

using Intervals = std::vector<std::pair<double, double>>;

// The stretches of [t0, t1] inside the boxes' union, sorted and disjoint.
Intervals inside(const std::vector<Bounds3>& boxes, const Ray& ray, double t0, double t1) {
    Intervals out;
    for (const Bounds3& b : boxes) {
        double a = t0, z = t1;
        if (clipToBox(b, ray.org, ray.dir, a, z) && z > a) out.emplace_back(a, z);
    }
    std::sort(out.begin(), out.end());
    Intervals merged;
    for (const auto& s : out)
        if (!merged.empty() && s.first <= merged.back().second) merged.back().second = std::max(merged.back().second, s.second);
        else merged.push_back(s);
    return merged;
}

double length(const Intervals& s) {
    double sum = 0;
    for (const auto& [a, b] : s) sum += b - a;
    return sum;
}

// The length of what a and b share (both sorted and disjoint).
double overlap(const Intervals& a, const Intervals& b) {
    double sum = 0;
    for (size_t i = 0, j = 0; i < a.size() && j < b.size();) {
        sum += std::max(0.0, std::min(a[i].second, b[j].second) - std::max(a[i].first, b[j].first));
        if (a[i].second < b[j].second) ++i;
        else ++j;
    }
    return sum;
}

std::vector<Bounds3> parseBoxes(const std::string& key, const std::string& text) {
    std::vector<Bounds3> boxes;
    std::stringstream all(text);
    for (std::string item; std::getline(all, item, ';');) {
        if (item.find_first_not_of(" \t\n") == std::string::npos) continue;
        std::istringstream in(item);
        double v[6];
        for (double& x : v)
            if (!(in >> x)) throw Error(key + ": expected six numbers per box, not '" + item + "'");
        std::string extra;
        if (in >> extra) throw Error(key + ": expected six numbers per box, not '" + item + "'");
        boxes.push_back({dvec3(v[0], v[1], v[2]), dvec3(v[3], v[4], v[5])});
    }
    return boxes;
}

void check(const std::string& key, const std::vector<Bounds3>& boxes) {
    for (const Bounds3& b : boxes)
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a]) || !(b.lo[a] < b.hi[a]))
                throw Error(key + ": a box must be finite and run from its lower corner to its upper one");
}

// Whether box b lies in the union of `boxes` (their union along the grid of all their faces: exact for boxes).
bool within(const Bounds3& b, const std::vector<Bounds3>& boxes) {
    std::vector<double> cuts[3];
    for (int a = 0; a < 3; ++a) {
        cuts[a] = {b.lo[a], b.hi[a]};
        for (const Bounds3& c : boxes)
            for (double x : {c.lo[a], c.hi[a]})
                if (x > b.lo[a] && x < b.hi[a]) cuts[a].push_back(x);
        std::sort(cuts[a].begin(), cuts[a].end());
    }
    for (size_t i = 0; i + 1 < cuts[0].size(); ++i)
        for (size_t j = 0; j + 1 < cuts[1].size(); ++j)
            for (size_t k = 0; k + 1 < cuts[2].size(); ++k) {
                dvec3 mid(0.5 * (cuts[0][i] + cuts[0][i + 1]), 0.5 * (cuts[1][j] + cuts[1][j + 1]),
                          0.5 * (cuts[2][k] + cuts[2][k + 1]));
                if (std::none_of(boxes.begin(), boxes.end(), [&](const Bounds3& c) { return c.contains(mid); }))
                    return false;
            }
    return true;
}

}  // namespace

DataCoverage::DataCoverage(std::vector<Bounds3> domain, std::vector<Bounds3> data, std::string note)
    : domain_(std::move(domain)), data_(std::move(data)), note_(std::move(note)) {
    check("brume:domain", domain_);
    check("brume:data", data_);
    incomplete_ = std::any_of(domain_.begin(), domain_.end(), [&](const Bounds3& b) { return !within(b, data_); });
}

DataCoverage DataCoverage::parse(const std::string& domain, const std::string& data, const std::string& note) {
    return DataCoverage(parseBoxes("brume:domain", domain), parseBoxes("brume:data", data), note);
}

std::string DataCoverage::format(const std::vector<Bounds3>& boxes) {
    std::ostringstream out;
    out.precision(9);
    for (size_t i = 0; i < boxes.size(); ++i) {
        const Bounds3& b = boxes[i];
        out << (i ? "; " : "") << b.lo.x << ' ' << b.lo.y << ' ' << b.lo.z << ' ' << b.hi.x << ' ' << b.hi.y << ' ' << b.hi.z;
    }
    return out.str();
}

double DataCoverage::uncoveredLength(const Ray& ray, double t0, double t1) const {
    if (!incomplete_ || !(t1 > t0)) return 0;
    Intervals domain = inside(domain_, ray, t0, t1);
    if (domain.empty()) return 0;
    return std::max(0.0, length(domain) - overlap(domain, inside(data_, ray, t0, t1)));
}

}  // namespace brume
