// Where a visibility study looks from: a grid of eye points over a floor (the cells of a map), or named
// waypoints along an escape route.
#pragma once
#include <istream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace brume {

struct Observer {
    std::string name;        // "cell_C_R" of a grid point (column, row); a waypoint's own name
    glm::dvec3 eye{0};
    int column = -1, row = -1;  // a grid point's cell in the map (row 0 at the largest y, as pictures go)
};

struct ObserverGrid {
    double x0 = 0, y0 = 0, step = 0;  // the corner of the cell (0, 0) at the smallest x and y
    int columns = 0, rows = 0;
};

// The centres of the cells of side `step` that fill the rectangle (x0, y0)–(x1, y1), at height z. Throws
// Error for an empty rectangle, a step ≤ 0, or more than 4 million points.
std::vector<Observer> gridObservers(const ObserverGrid& grid, double z);
ObserverGrid makeGrid(double x0, double y0, double x1, double y1, double step);

// Waypoints, one per line: "name x y z" ('#' starts a comment). Throws Error "file:line: what is wrong".
std::vector<Observer> readWaypoints(std::istream& in, const std::string& file);

}  // namespace brume
