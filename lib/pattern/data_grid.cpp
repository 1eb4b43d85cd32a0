#include "pattern/data_grid.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <sstream>

#include "scene/raypath.h"
#include "spectrum/embedded_spectra.h"
#include "util/error.h"

namespace brume {

DataGrid::DataGrid(std::vector<Axis> axes, int channels, std::vector<float> values)
    : axes_(std::move(axes)), strides_(axes_.size()), channels_(channels), values_(std::move(values)) {
    assert(channels_ >= 1 && channels_ <= kMaxChannels);
    size_t stride = size_t(channels_);
    for (size_t d = axes_.size(); d-- > 0;) {
        strides_[d] = stride;
        stride *= size_t(axes_[d].count);
    }
}

namespace {

// Whitespace-separated numbers with '#' comments to the end of the line, remembering where each was.
class NumberReader {
public:
    NumberReader(std::istream& in, std::string name) : in_(in), name_(std::move(name)) {}

    double next(const char* what) {
        std::string word = nextWord();
        if (word.empty()) throw Error(SourceLocation{name_, line_}, std::string("unexpected end of file, expected ") + what);
        char* end;
        double v = std::strtod(word.c_str(), &end);
        if (*end || !std::isfinite(v))
            throw Error(where(), "bad " + std::string(what) + " \"" + word + "\"");
        return v;
    }
    int count(const char* what, int lo, int hi) {
        double v = next(what);
        if (v != std::floor(v) || v < lo || v > hi)
            throw Error(where(), std::string("bad ") + what);
        return int(v);
    }
    SourceLocation where() const { return {name_, wordLine_}; }  // of the last word read

private:
    std::string nextWord() {
        std::string word;
        for (int c; (c = in_.get()) != EOF;) {
            if (c == '#') {
                while ((c = in_.get()) != EOF && c != '\n') {}
            }
            if (c == '\n') ++line_;
            if (c == EOF || std::isspace(c)) {
                if (!word.empty()) return word;
                continue;
            }
            if (word.empty()) wordLine_ = line_;
            word += char(c);
        }
        return word;
    }

    std::istream& in_;
    std::string name_;
    int line_ = 1, wordLine_ = 1;
};

constexpr double kMaxValues = 1e9;

DataGrid::Axis readAxis(NumberReader& r) {
    DataGrid::Axis a;
    a.begin = r.next("axis start");
    a.end = r.next("axis end");
    a.count = r.count("node count", 2, 1 << 30);
    if (a.begin != a.end) return a;
    // "0 0 n p1 … pn": nodes at given, monotonic points.
    SourceLocation where = r.where();
    for (int i = 0; i < a.count; ++i) a.points.push_back(r.next("axis point"));
    bool rising = a.points[1] > a.points[0];
    for (int i = 1; i < a.count; ++i)
        if ((a.points[i] > a.points[i - 1]) != rising || a.points[i] == a.points[i - 1])
            throw Error(where, "axis points are not monotonic");
    a.begin = a.points.front();
    a.end = a.points.back();
    return a;
}

}  // namespace

DataGrid DataGrid::readDataFile(const std::string& name) {
    FileText file = readLibraryFile(name, embeddedSpectrumFiles(), "data file");
    std::istringstream in(file.text);
    return read(in, file.origin);
}

DataGrid DataGrid::read(std::istream& in, const std::string& name) {
    NumberReader r(in, name);
    int n = r.count("number of dimensions", 1, kMaxDimensions);
    std::vector<Axis> axes;
    double size = 1;
    for (int d = 0; d < n; ++d) {
        axes.push_back(readAxis(r));
        size *= axes.back().count;
        if (size > kMaxValues) throw Error(r.where(), "data array too large");
    }
    // Grown as values arrive, so that a header promising more than the file holds costs nothing.
    std::vector<float> values;
    values.reserve(size_t(std::min(size, 1e6)));
    for (size_t i = 0; i < size_t(size); ++i) {
        values.push_back(float(r.next("data value")));
        if (!std::isfinite(values.back())) throw Error(r.where(), "data value beyond single precision");
    }
    return DataGrid(std::move(axes), 1, std::move(values));
}

namespace {

// Radiance's colorpict coordinates of a picture's rows (v) and columns (u): the smaller side spans 1, pixel
// aspect included.
std::vector<DataGrid::Axis> pictureAxes(const Picture& p) {
    if (p.width < 2 || p.height < 2) throw Error("picture too small for a pattern (needs 2 × 2 pixels)");
    double v = 1, u = 1;
    if (p.width <= p.height * p.pixelAspect) v = p.pixelAspect * p.height / p.width;
    else u = double(p.width) / p.height / p.pixelAspect;
    return {DataGrid::Axis{0, v, p.height, {}}, DataGrid::Axis{0, u, p.width, {}}};
}

// Pixel rows from the top, `n` values per pixel, with the first node row at the bottom of the picture.
std::vector<float> bottomUp(const float* rows, int width, int height, size_t n) {
    std::vector<float> values(size_t(width) * height * n);
    size_t row = size_t(width) * n;
    for (int y = 0; y < height; ++y) std::copy_n(rows + size_t(height - 1 - y) * row, row, &values[size_t(y) * row]);
    return values;
}

}  // namespace

DataGrid DataGrid::fromPicture(const Picture& p) {
    return DataGrid(pictureAxes(p), 3, bottomUp(p.pixels.data(), p.width, p.height, 3));
}

DataGrid DataGrid::fromHyperspectralPicture(const HyperspectralPicture& h) {
    std::vector<Axis> axes = pictureAxes(h.picture);
    double half = 0.5 * (h.last - h.first) / h.bands;
    axes.push_back(Axis{h.first + half, h.last - half, h.bands, {}});
    return DataGrid(std::move(axes), 1, bottomUp(h.values.data(), h.picture.width, h.picture.height, size_t(h.bands)));
}

namespace {

// Where `x` falls along an axis, in node units: its lower node i (0 … count−2) and fractional position.
std::pair<int, double> locate(const DataGrid::Axis& a, double x) {
    int last = a.count - 2;
    if (a.points.empty()) {
        double f = (x - a.begin) / (a.end - a.begin) * (a.count - 1);
        int i = std::clamp(int(std::clamp(f, -1.0, double(a.count))), 0, last);
        return {i, f};
    }
    bool rising = a.points[1] > a.points[0];
    auto after = rising ? std::upper_bound(a.points.begin(), a.points.end(), x)
                        : std::upper_bound(a.points.begin(), a.points.end(), x, std::greater<double>());
    int i = std::clamp(int(after - a.points.begin()) - 1, 0, last);
    return {i, i + (x - a.points[i]) / (a.points[i + 1] - a.points[i])};
}

}  // namespace

void DataGrid::interpolate(std::span<const double> point, float* out) const {
    double sum[kMaxChannels] = {};
    accumulate(point, 0, 0, 1.0, sum);
    // Extrapolating values near the largest float can pass it: kept finite.
    constexpr double kLargest = std::numeric_limits<float>::max();
    for (int c = 0; c < channels_; ++c) out[c] = float(std::clamp(sum[c], -kLargest, kLargest));
}

void DataGrid::accumulate(std::span<const double> point, size_t offset, int dim, double coef, double* out) const {
    if (!std::isfinite(point[dim])) return;  // nowhere on the grid: contributes nothing
    auto [i, x] = locate(axes_[dim], point[dim]);
    double c0, c1;
    // Linear within the grid and one division beyond it; further out tapering to zero (Radiance's data.c).
    if (x > i + 2) {
        c0 = 1 / (i - 1 - x);
        c1 = -2 * c0;
    } else if (x < i - 1) {
        c1 = 1 / (x - i);
        c0 = -2 * c1;
    } else {
        c0 = i + 1 - x;
        c1 = x - i;
    }
    size_t at = offset + size_t(i) * strides_[dim];
    if (dim + 1 == dimensions()) {
        for (int c = 0; c < channels_; ++c)
            out[c] += coef * (c0 * values_[at + c] + c1 * values_[at + strides_[dim] + c]);
        return;
    }
    accumulate(point, at, dim + 1, coef * c0, out);
    accumulate(point, at + strides_[dim], dim + 1, coef * c1, out);
}

}  // namespace brume
