// Values tabulated on an n-dimensional grid and interpolated between its nodes, as Radiance's data files
// (brightdata, colordata, texdata, mixdata, ies2rad distributions) and pictures (colorpict) are.
#pragma once
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "io/picture.h"

namespace brume {

class DataGrid {
public:
    static constexpr int kMaxDimensions = 16;
    static constexpr int kMaxChannels = 3;

    // One dimension: `count` nodes evenly spaced from `begin` to `end`, or at the given points (monotonic).
    struct Axis {
        double begin = 0, end = 1;
        int count = 2;
        std::vector<double> points;
    };

    DataGrid(std::vector<Axis> axes, int channels, std::vector<float> values);

    // A Radiance data file, found along RAYPATH or else among Brume's shipped spectra (cie_d65.dat …,
    // spectrum/embedded_spectra.h). Throws Error (file:line) when it is malformed.
    static DataGrid readDataFile(const std::string& name);
    // The same from a stream; `name` for messages.
    static DataGrid read(std::istream& in, const std::string& name);
    // A picture as colorpict sees it: two dimensions, v (rows, from the bottom) then u (columns), the
    // smaller one spanning 0…1 and the other its aspect ratio; three channels.
    static DataGrid fromPicture(const Picture& picture);
    // A hyperspectral picture as specpict sees it: v and u as for a picture, then wavelength (the bands'
    // centres, longest first); one channel.
    static DataGrid fromHyperspectralPicture(const HyperspectralPicture& picture);

    int dimensions() const { return int(axes_.size()); }
    int channels() const { return channels_; }
    const std::vector<Axis>& axes() const { return axes_; }

    // Multilinear interpolation at `point` (one coordinate per dimension) into out[channels()]. Outside the
    // grid values are extrapolated for one more division, then taper off to zero, as Radiance does.
    void interpolate(std::span<const double> point, float* out) const;

private:
    void accumulate(std::span<const double> point, size_t offset, int dim, double coef, double* out) const;

    std::vector<Axis> axes_;
    std::vector<size_t> strides_;  // values between neighbouring nodes along each axis
    int channels_;
    std::vector<float> values_;  // later dimensions vary faster, channels fastest
};

}  // namespace brume
