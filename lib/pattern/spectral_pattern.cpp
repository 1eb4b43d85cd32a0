#include "pattern/spectral_pattern.h"

#include <algorithm>
#include <cmath>

#include "pattern/function_object.h"
#include "spectrum/binned_spectrum.h"
#include "spectrum/spectral_sampling.h"
#include "util/error.h"

namespace brume {

namespace {

class ConstantSpectrum : public Pattern {
public:
    explicit ConstantSpectrum(Spectrum s) : s_(std::move(s)) {}
    void apply(const PatternHit&, PatternEvaluator&, Texturing& t) const override { t.color *= s_; }

private:
    Spectrum s_;
};

// Samples at equal steps from `first` to `last` stand for bins centred on them: the bins reach half a step
// beyond either end (Radiance's p_spectrum and p_specfile).
Spectrum fromSamples(const std::vector<double>& v, double first, double last) {
    double half = 0.5 * (last - first) / double(v.size() - 1);
    return spectrumFromBins(v, first - half, last + half);
}

// spectrum: 0 0 5+ nmA nmB s1 … sN.
std::unique_ptr<Pattern> constantSpectrum(const SceneObject& o) {
    if (!o.strings.empty() || !o.integers.empty() || o.reals.size() < 5) badArguments(o, "expected 0 0 5+ nmA nmB s1 s2 s3 …");
    if (o.reals[0] == o.reals[1]) badArguments(o, "the wavelengths nmA and nmB must differ");
    std::vector<double> v(o.reals.begin() + 2, o.reals.end());
    return std::make_unique<ConstantSpectrum>(fromSamples(v, o.reals[0], o.reals[1]));
}

// A data file's axis, as (first node, last node, node count).
struct Nodes {
    double first, last;
    int count;
};
Nodes nodesOf(const DataGrid::Axis& a) {
    if (a.points.empty()) return {a.begin, a.end, a.count};
    return {a.points.front(), a.points.back(), int(a.points.size())};
}

// specfile: 1 datafile 0 0, a 1-dimensional data file of values over wavelength. Values at unevenly spaced
// wavelengths are resampled at twice their count, as Radiance does.
std::unique_ptr<Pattern> fileSpectrum(const SceneObject& o, PatternLibrary& lib) {
    if (o.strings.size() != 1 || !o.integers.empty() || !o.reals.empty()) badArguments(o, "expected 1 datafile 0 0");
    const DataGrid& g = lib.dataFile(o.strings[0]);
    if (g.dimensions() != 1 || g.channels() != 1)
        throw Error(o.where, "specfile \"" + o.name + "\": data file " + o.strings[0] + " must be 1-dimensional");
    Nodes n = nodesOf(g.axes()[0]);
    int count = g.axes()[0].points.empty() ? n.count : 2 * n.count;
    std::vector<double> v(static_cast<size_t>(count));
    for (int k = 0; k < count; ++k) {
        double nm = n.first + (n.last - n.first) * k / (count - 1);
        float value;
        g.interpolate(std::span<const double>(&nm, 1), &value);
        v[size_t(k)] = value;
    }
    return std::make_unique<ConstantSpectrum>(fromSamples(v, n.first, n.last));
}

// specfunc: 2+ sfunc funcfile transform 0 2+ nmA nmB A3 …: the function of wavelength, evaluated at the
// centres of bins across the range the sampling and nmA…nmB share (24 bins, or one per band if finer).
class FunctionSpectrum : public Pattern {
public:
    FunctionSpectrum(const SceneObject& o, PatternLibrary& lib) : f_(functionObject(o, lib, 1, 2, 0)) {
        if (o.reals.size() < 2) badArguments(o, "expected 2+ reals nmA nmB …");
        const SpectralSampling& s = spectralSampling();
        from_ = std::min(std::max(o.reals[0], o.reals[1]), s.longest);
        to_ = std::max(std::min(o.reals[0], o.reals[1]), s.shortest);
        if (!(from_ > to_)) throw Error(o.where, "specfunc \"" + o.name + "\": its range lies outside the spectral range");
        double bands = s.isRgb() ? 0 : (from_ - to_) / ((s.longest - s.shortest) / s.channels);
        bins_ = std::max(24, int(std::ceil(bands - 1e-9)));
        function_ = lib.function(o.strings[0], 1, f_.scope, o.where);
    }
    void apply(const PatternHit& hit, PatternEvaluator& e, Texturing& t) const override {
        cal::Evaluator& eval = f_.begin(hit, e);
        double v[Spectrum::kMaxChannels];
        for (int k = 0; k < bins_; ++k) {
            double nm = from_ + (to_ - from_) * (k + 0.5) / bins_;
            v[k] = eval(function_, std::span<const double>(&nm, 1));
        }
        t.color *= spectrumFromBins(std::span<const double>(v, size_t(bins_)), from_, to_).clampFinite();
    }

private:
    FunctionObject f_;
    cal::FuncId function_;
    double from_, to_;
    int bins_;
};

// specdata: 3+n+ func datafile funcfile x1 … xn transform 0 m A1 … Am: an (n+1)-dimensional data file whose
// last dimension is wavelength; func(value, wavelength) of each interpolated sample makes the spectrum.
// specpict: 5+ func picture funcfile u v transform 0 m A1 … Am: the same of a hyperspectral picture.
class DataSpectrum : public Pattern {
public:
    DataSpectrum(const SceneObject& o, PatternLibrary& lib, bool picture) : picture_(picture) {
        if (o.strings.size() < (picture ? 5u : 4u)) badArguments(o, "too few string arguments");
        grid_ = picture ? &lib.hyperspectralPicture(o.strings[1]) : &lib.dataFile(o.strings[1]);
        int dims = grid_->dimensions();
        if (dims < 2 || grid_->channels() != 1)
            throw Error(o.where, "specdata \"" + o.name + "\": data file " + o.strings[1] + " needs at least 2 dimensions");
        f_ = functionObject(o, lib, 2, 3, size_t(dims - 1));
        function_ = lib.function(o.strings[0], 2, f_.scope, o.where);
        wavelengths_ = nodesOf(grid_->axes().back());
        if (wavelengths_.count > Spectrum::kMaxChannels * 4)
            throw Error(o.where, "specdata \"" + o.name + "\": too many wavelengths in " + o.strings[1]);
    }
    void apply(const PatternHit& hit, PatternEvaluator& e, Texturing& t) const override {
        cal::Evaluator& eval = f_.begin(hit, e);
        double point[DataGrid::kMaxDimensions];
        size_t n = f_.exprs.size();
        for (size_t i = 0; i < n; ++i) point[i] = eval(f_.exprs[i]);
        if (picture_) std::swap(point[0], point[1]);  // u, v looked up as rows (v), then columns (u)
        const Nodes& w = wavelengths_;
        std::vector<double> v(static_cast<size_t>(w.count));
        for (int k = 0; k < w.count; ++k) {
            double nm = w.count > 1 ? w.first + (w.last - w.first) * k / (w.count - 1) : w.first;
            point[n] = nm;
            float value;
            grid_->interpolate(std::span<const double>(point, n + 1), &value);
            double args[2] = {value, nm};
            v[size_t(k)] = e.eval(function_, args);
        }
        t.color *= fromSamples(v, w.first, w.last).clampFinite();
    }

private:
    bool picture_;
    const DataGrid* grid_;
    FunctionObject f_;
    cal::FuncId function_;
    Nodes wavelengths_;
};

}  // namespace

bool isSpectralPatternType(const std::string& t) {
    return t == "spectrum" || t == "specfile" || t == "specfunc" || t == "specdata" || t == "specpict";
}

std::unique_ptr<Pattern> makeSpectralPattern(const SceneObject& o, PatternLibrary& lib) {
    if (o.type == "spectrum") return constantSpectrum(o);
    if (o.type == "specfile") return fileSpectrum(o, lib);
    if (o.type == "specfunc") return std::make_unique<FunctionSpectrum>(o, lib);
    return std::make_unique<DataSpectrum>(o, lib, o.type == "specpict");
}

}  // namespace brume
