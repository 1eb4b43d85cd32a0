#include "daylight/sensor_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <unordered_map>

#include <glm/common.hpp>

#include "util/error.h"

namespace brume {

namespace {

// At most this many pixels a side: a plan of thousands of sensors stays a picture one can open.
constexpr double kMaxSide = 2048;
// Pixels a sensor's spacing spans: enough to see each cell as a square.
constexpr double kPixelsPerSpacing = 8;

// Sensors in square buckets of side `size` over the plan, to find the nearest ones to a point by looking
// in its bucket and the rings around it.
class Buckets {
public:
    Buckets(const std::vector<dvec3>& sensors, double size) : sensors_(sensors), size_(size) {
        for (size_t i = 0; i < sensors.size(); ++i) cells_[key(cell(sensors[i].x), cell(sensors[i].y))].push_back(int(i));
    }
    // The nearest sensor to (x, y) but `skip`, looking `rings` rings of buckets around its own; -1 if none
    // is within `reach`. The lower index wins a tie.
    int nearest(double x, double y, double reach, int rings = 1, int skip = -1) const {
        int best = -1;
        double d2 = reach * reach;
        const long cx = cell(x), cy = cell(y);
        for (long i = cx - rings; i <= cx + rings; ++i)
            for (long j = cy - rings; j <= cy + rings; ++j) {
                auto it = cells_.find(key(i, j));
                if (it == cells_.end()) continue;
                for (int s : it->second) {
                    double dx = sensors_[s].x - x, dy = sensors_[s].y - y, d = dx * dx + dy * dy;
                    if (s != skip && (d < d2 || (d == d2 && (best < 0 || s < best)))) best = s, d2 = d;
                }
            }
        return best;
    }
    // The sensor nearest to sensor i but itself (all lie within `extent`, the plan's size, of each other).
    int nearestOther(int i, double extent) const {
        const dvec3& p = sensors_[i];
        for (long rings = 1;; rings *= 2) {
            // A sensor found within `rings` buckets may lie farther than an unsearched one, unless it is
            // within (rings) bucket sizes of the point.
            int s = nearest(p.x, p.y, std::min(double(rings) * size_, 2 * extent), int(rings), i);
            if (s >= 0) return s;
        }
    }

private:
    long cell(double v) const { return long(std::floor(v / size_)); }
    static long long key(long i, long j) { return (static_cast<long long>(i) << 32) ^ (j & 0xffffffffLL); }
    const std::vector<dvec3>& sensors_;
    double size_;
    std::unordered_map<long long, std::vector<int>> cells_;
};

}  // namespace

SensorPlan::SensorPlan(const std::vector<dvec3>& sensors) : sensors_(sensors.size()) {
    if (sensors.empty()) throw Error("no sensors to draw a plan of");
    dvec3 lo = sensors[0], hi = sensors[0];
    for (const dvec3& s : sensors) lo = glm::min(lo, s), hi = glm::max(hi, s);
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, 1e-9});
    std::vector<double> nearest;
    if (sensors.size() > 1) {
        // Buckets about one grid step wide: the nearest neighbour is in the first ring or two of them.
        Buckets buckets(sensors, std::max(extent / std::sqrt(double(sensors.size())), 1e-9 * extent));
        for (size_t i = 0; i < sensors.size(); ++i) {
            int other = buckets.nearestOther(int(i), extent);
            double d = std::hypot(sensors[other].x - sensors[i].x, sensors[other].y - sensors[i].y);
            if (d <= 1e-9 * extent)
                throw Error("sensors " + std::to_string(i) + " and " + std::to_string(other) +
                            " share x and y (a grid on two storeys?): one plan a storey");
            nearest.push_back(d);
        }
    }
    if (nearest.empty()) spacing_ = 1;
    else {
        std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
        spacing_ = nearest[nearest.size() / 2];
    }
    pixel_ = std::max(spacing_ / kPixelsPerSpacing, (extent + spacing_) / kMaxSide);
    corner_ = dvec3(lo.x - spacing_ / 2, lo.y - spacing_ / 2, hi.z);
    width_ = int(std::ceil((hi.x - lo.x + spacing_) / pixel_));
    height_ = int(std::ceil((hi.y - lo.y + spacing_) / pixel_));
    // A pixel belongs to the nearest sensor within the spacing's reach: a square grid's cells fill the plan
    // to its border (their corners are spacing/√2 away), and no cell reaches across a gap wider than that.
    Buckets cells(sensors, spacing_);
    owner_.assign(size_t(width_) * height_, -1);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            owner_[size_t(y) * width_ + x] =
                cells.nearest(corner_.x + (x + 0.5) * pixel_, corner_.y + (height_ - y - 0.5) * pixel_, 0.75 * spacing_);
        }
}

Picture SensorPlan::map(const std::vector<double>& values, std::vector<std::string> lines) const {
    if (values.size() != sensors_)
        throw Error(std::to_string(values.size()) + " values for a plan of " + std::to_string(sensors_) + " sensors");
    Picture p;
    p.width = width_, p.height = height_;
    p.pixels.assign(size_t(width_) * height_ * 3, 0.f);
    for (size_t i = 0; i < owner_.size(); ++i)
        if (owner_[i] >= 0) std::fill_n(&p.pixels[3 * i], 3, float(std::max(0.0, values[owner_[i]])));
    const double w = width_ * pixel_, h = height_ * pixel_;
    char view[256];
    std::snprintf(view, sizeof view, "VIEW= -vtl -vp %.12g %.12g %.12g -vd 0 0 -1 -vu 0 1 0 -vh %.12g -vv %.12g",
                  corner_.x + w / 2, corner_.y + h / 2, corner_.z, w, h);
    lines.push_back(view);
    p.header = std::move(lines);
    return p;
}

}  // namespace brume
