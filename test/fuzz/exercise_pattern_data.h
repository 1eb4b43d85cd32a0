// What the picture and data-file fuzz targets do with one input, shared with the corpus replay test: read it
// as colorpict, specpict and the *data patterns do, then look values up inside, at and far beyond the grid's edges.
// Errors (brume::Error) are fine; crashes are not, and a value that is not a finite number makes these
// return false.
#pragma once
#include <cmath>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "io/picture.h"
#include "pattern/data_grid.h"
#include "util/error.h"

namespace brume {

inline bool lookupsAreFinite(const DataGrid& grid) {
    std::vector<double> point(grid.dimensions());
    std::vector<float> out(grid.channels());
    for (double t : {-1e300, -0.5, 0.0, 0.37, 1.0, 1.3, 1e300}) {
        for (int d = 0; d < grid.dimensions(); ++d) {
            const DataGrid::Axis& a = grid.axes()[d];
            point[d] = a.begin + (t + 0.11 * d) * (a.end - a.begin);
        }
        grid.interpolate(point, out.data());
        for (float v : out)
            if (!std::isfinite(v)) return false;
    }
    return true;
}

inline bool exerciseDataFile(std::string_view bytes) {
    std::istringstream in{std::string(bytes)};
    try {
        return lookupsAreFinite(DataGrid::read(in, "fuzz.dat"));
    } catch (const Error&) {
        return true;
    }
}

// As colorpict reads it, then as specpict reads a hyperspectral picture.
inline bool exercisePicture(std::string_view bytes) {
    bool finite = true;
    try {
        std::istringstream in{std::string(bytes)};
        finite = lookupsAreFinite(DataGrid::fromPicture(readRadiancePicture(in, "fuzz.hdr")));
    } catch (const Error&) {
    }
    try {
        std::istringstream in{std::string(bytes)};
        finite = lookupsAreFinite(DataGrid::fromHyperspectralPicture(readHyperspectralPicture(in, "fuzz.hsr"))) && finite;
    } catch (const Error&) {
    }
    return finite;
}

}  // namespace brume
