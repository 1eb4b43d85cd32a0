// A sensor grid seen from above: a picture of the sensors' x and y in which each pixel shows the value of
// the nearest sensor within its cell, so that a metric per sensor (DA, UDI) can be read over the floor
// plan, as Radiance's falsecolor draws it. Any layout works (rotated rooms, L-shaped grids): a sensor's
// cell is the part of the plan nearer to it than to any other, out to the grid's spacing.
#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include "io/picture.h"

namespace brume {

using glm::dvec3;

class SensorPlan {
public:
    // The plan of `sensors` (their x and y; z places the view). Throws Error for none, or for two sensors at
    // the same x and y (a grid on two storeys: one plan a storey).
    explicit SensorPlan(const std::vector<dvec3>& sensors);

    // The median distance from a sensor to its nearest neighbour in x and y (1 for a single sensor).
    double spacing() const { return spacing_; }
    int width() const { return width_; }
    int height() const { return height_; }
    // The sensor a pixel shows (row 0 at the largest y), -1 for none (outside every cell).
    int sensorAt(int x, int y) const { return owner_[size_t(y) * width_ + x]; }

    // The picture of one value a sensor (negative values as 0), R = G = B, 0 outside the cells; the header
    // gets `lines` and a parallel VIEW looking down from the sensors' highest z (+x right, +y up), with
    // which rpict draws the floor beneath the map.
    Picture map(const std::vector<double>& values, std::vector<std::string> lines) const;

private:
    size_t sensors_;
    double spacing_, pixel_;
    dvec3 corner_;  // the plan's smallest x and y, the sensors' largest z
    int width_, height_;
    std::vector<int> owner_;
};

}  // namespace brume
