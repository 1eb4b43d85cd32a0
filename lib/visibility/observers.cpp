#include "visibility/observers.h"

#include <cmath>

#include "util/error.h"
#include "visibility/line_words.h"

namespace brume {


ObserverGrid makeGrid(double x0, double y0, double x1, double y1, double step) {
    if (!(step > 0)) throw Error("the grid's step must be > 0");
    if (!(x1 > x0 && y1 > y0)) throw Error("the grid's rectangle is empty: x1 > x0 and y1 > y0 are needed");
    double columns = std::round((x1 - x0) / step), rows = std::round((y1 - y0) / step);
    if (columns * rows > 4e6) throw Error("the grid has more than 4 million points: take a larger step");
    return {x0, y0, step, std::max(1, int(columns)), std::max(1, int(rows))};
}

std::vector<Observer> gridObservers(const ObserverGrid& g, double z) {
    std::vector<Observer> out;
    for (int row = 0; row < g.rows; ++row)
        for (int column = 0; column < g.columns; ++column) {
            double x = g.x0 + (column + 0.5) * g.step, y = g.y0 + (g.rows - row - 0.5) * g.step;
            out.push_back({"cell_" + std::to_string(column) + "_" + std::to_string(row), {x, y, z}, column, row});
        }
    return out;
}

std::vector<Observer> readWaypoints(std::istream& in, const std::string& file) {
    std::vector<Observer> out;
    forEachWordLine(in, file, [&](const std::vector<std::string>& w, const std::string& where) {
        if (w.size() != 4) throw Error(where + ": expected 'name x y z', found " + std::to_string(w.size()) + " words");
        if (w[0].find_first_of(",\"") != std::string::npos)
            throw Error(where + ": waypoint '" + w[0] + "': a name without commas or quotes, for the CSV");
        for (const Observer& o : out)
            if (o.name == w[0]) throw Error(where + ": waypoint '" + w[0] + "' is named twice");
        out.push_back({w[0], {realWord(w[1], where, "x"), realWord(w[2], where, "y"), realWord(w[3], where, "z")}});
    });
    if (out.empty()) throw Error(file + ": no waypoints");
    return out;
}

}  // namespace brume
