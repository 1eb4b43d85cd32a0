#include "spectrum/rgb_to_spectrum.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include "spectrum/cie_tables.h"
#include "spectrum/colorimetry.h"
#include "spectrum/spectral_sampling.h"

namespace brume {

namespace {

constexpr double kFirst = 360, kLast = 830;  // nm: the CIE 1931 observer's range, t = 0…1 over it
constexpr double kFitStep = 10;              // nm between the wavelengths the fit integrates over
constexpr int kResolution = 24;              // table nodes per axis

double scaled(double nm) { return (nm - kFirst) / (kLast - kFirst); }
double sigmoid(double x) { return 0.5 + x / (2 * std::sqrt(1 + x * x)); }
// The constant term of a flat spectrum of value z, σ⁻¹(z), below z = ½ where it is far from linear in z;
// continued by its tangent above (σ⁻¹ grows without bound toward 1, where the table's nodes crowd).
double darkOffset(double z) {
    if (z >= 0.5) return 2 * (z - 0.5);
    z = std::max(z, 1e-6);
    return (2 * z - 1) / (2 * std::sqrt(z * (1 - z)));
}

// RGB of a spectrum as a weighted sum of its values at the fit's wavelengths (trapezoid rule over each
// normalised CMF, then Radiance's XYZ to RGB).
struct ColourWeights {
    std::vector<double> t;
    std::vector<Color3> rgb;

    ColourWeights() {
        int n = int(std::lround((kLast - kFirst) / kFitStep)) + 1;
        Color3 area{cieX().integral(kFirst, kLast), cieY().integral(kFirst, kLast), cieZ().integral(kFirst, kLast)};
        Matrix3 m = xyzToRgb(kRadiancePrimaries);
        for (int j = 0; j < n; ++j) {
            double nm = kFirst + j * kFitStep, dx = (j == 0 || j == n - 1) ? kFitStep / 2 : kFitStep;
            Color3 xyz{cieX().at(nm) * dx / area[0], cieY().at(nm) * dx / area[1], cieZ().at(nm) * dx / area[2]};
            t.push_back(scaled(nm));
            rgb.push_back(m * xyz);
        }
    }
};

// Fits c so that the spectrum's colour is `target`: Levenberg–Marquardt on the RGB residual, from `c`.
void fit(const ColourWeights& w, const Color3& target, SigmoidCoefficients& c) {
    auto residual = [&](const SigmoidCoefficients& k, Matrix3* jacobian) {
        Color3 r{-target[0], -target[1], -target[2]};
        if (jacobian) *jacobian = Matrix3{};
        for (size_t j = 0; j < w.t.size(); ++j) {
            double t = w.t[j], x = (k[0] * t + k[1]) * t + k[2];
            double root = std::sqrt(1 + x * x);
            double s = 0.5 + x / (2 * root), ds = 0.5 / ((1 + x * x) * root);
            double dk[3] = {ds * t * t, ds * t, ds};
            for (int i = 0; i < 3; ++i) {
                r[i] += s * w.rgb[j][i];
                if (jacobian)
                    for (int q = 0; q < 3; ++q) (*jacobian)[i][q] += dk[q] * w.rgb[j][i];
            }
        }
        return r;
    };
    auto norm2 = [](const Color3& r) { return r[0] * r[0] + r[1] * r[1] + r[2] * r[2]; };
    // Far below the table's own interpolation error.
    double tolerance = 1e-6 * std::max({target[0], target[1], target[2], 1e-3});
    double lambda = 1e-3;
    Matrix3 jac;
    Color3 r = residual(c, &jac);
    for (int iteration = 0; iteration < 100 && norm2(r) > tolerance * tolerance; ++iteration) {
        Matrix3 jtj{};
        Color3 jtr{};
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                for (int i = 0; i < 3; ++i) jtj[a][b] += jac[i][a] * jac[i][b];
        for (int a = 0; a < 3; ++a)
            for (int i = 0; i < 3; ++i) jtr[a] += jac[i][a] * r[i];
        bool improved = false;
        for (int attempt = 0; attempt < 20 && !improved; ++attempt) {
            Matrix3 m = jtj;
            for (int a = 0; a < 3; ++a) m[a][a] += lambda * (jtj[a][a] + 1e-12);
            if (!(std::abs(determinant(m)) > 0)) {
                lambda *= 10;
                continue;
            }
            Color3 step = inverse(m) * Color3{-jtr[0], -jtr[1], -jtr[2]};
            SigmoidCoefficients next{c[0] + step[0], c[1] + step[1], c[2] + step[2]};
            Matrix3 nextJac;
            Color3 nr = residual(next, &nextJac);
            if (norm2(nr) < norm2(r)) {
                c = next, r = nr, jac = nextJac, improved = true;
                lambda = std::max(lambda / 10, 1e-9);
            } else {
                lambda *= 10;
            }
        }
        if (!improved) break;  // out of gamut: as close as the family gets
    }
}

// Nodes in brightness crowd toward black and white, where spectra change fastest (the paper's spacing).
double brightnessNode(int k) {
    auto smoothstep = [](double x) { return x * x * (3 - 2 * x); };
    return smoothstep(smoothstep(double(k) / (kResolution - 1)));
}

// Coefficients per node: for the largest channel m (3), the other two channels relative to it (x, y) and
// the largest channel's value (z, at brightnessNode). Fitted a line of nodes along z at a time, when a
// lookup first needs it: a scene's few colours cost a few lines (~0.2 ms each), not the whole table.
class CoefficientTable {
public:
    CoefficientTable() : nodes_(size_t(kLines) * kResolution), fitted_(new std::once_flag[kLines]) {
        for (int k = 0; k < kResolution; ++k) z_[k] = brightnessNode(k);
    }

    SigmoidCoefficients lookup(double r, double g, double b) const {
        double v[3] = {r, g, b};
        int m = int(std::max_element(v, v + 3) - v);
        double z = v[m];
        double x = v[(m + 1) % 3] / z * (kResolution - 1), y = v[(m + 2) % 3] / z * (kResolution - 1);
        int xi = std::min(int(x), kResolution - 2), yi = std::min(int(y), kResolution - 2);
        int zi = int(std::upper_bound(z_, z_ + kResolution, z) - z_) - 1;
        zi = std::clamp(zi, 0, kResolution - 2);
        double fx = x - xi, fy = y - yi, fz = (z - z_[zi]) / (z_[zi + 1] - z_[zi]);
        // Toward black the constant term follows σ⁻¹ of the brightness, far from linear: interpolate what
        // is left of it (nodes store c₂ − darkOffset(z)).
        SigmoidCoefficients c{0, 0, darkOffset(z)};
        for (int corner = 0; corner < 8; ++corner) {
            int dx = corner & 1, dy = corner >> 1 & 1, dz = corner >> 2 & 1;
            double weight = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy) * (dz ? fz : 1 - fz);
            const SigmoidCoefficients& n = line(m, xi + dx, yi + dy)[zi + dz];
            for (int q = 0; q < 3; ++q) c[q] += weight * n[q];
        }
        return c;
    }

private:
    static constexpr int kLines = 3 * kResolution * kResolution;

    // The nodes of line (m, i, j), fitted on first use.
    const SigmoidCoefficients* line(int m, int i, int j) const {
        int index = (m * kResolution + i) * kResolution + j;
        SigmoidCoefficients* nodes = &nodes_[size_t(index) * kResolution];
        std::call_once(fitted_[index], [&] { fitLine(m, i, j, nodes); });
        return nodes;
    }

    // Fitting from scratch at black or a saturated colour can fail; continuation from a mid brightness,
    // each node starting from its neighbour's solution, does not (Jakob and Hanika §4).
    void fitLine(int m, int i, int j, SigmoidCoefficients* nodes) const {
        static const ColourWeights w;
        auto solve = [&](int k, SigmoidCoefficients& c) {
            double z = z_[k];
            Color3 target;
            target[size_t(m)] = z;
            target[size_t((m + 1) % 3)] = z * i / (kResolution - 1);
            target[size_t((m + 2) % 3)] = z * j / (kResolution - 1);
            fit(w, target, c);
            nodes[k] = {c[0], c[1], c[2] - darkOffset(z)};
        };
        int start = kResolution / 5;
        SigmoidCoefficients c{0, 0, 0};
        for (int k = start; k < kResolution; ++k) solve(k, c);
        c = nodes[start];
        c[2] += darkOffset(z_[start]);
        for (int k = start - 1; k >= 0; --k) solve(k, c);
    }

    double z_[kResolution];
    mutable std::vector<SigmoidCoefficients> nodes_;
    std::unique_ptr<std::once_flag[]> fitted_;
};

const CoefficientTable& table() {
    static const CoefficientTable t;
    return t;
}

// Radiance's setscolor: each channel flat over its partition of the range.
Spectrum boxSpectrum(double r, double g, double b, const SpectralSampling& s) {
    auto split = s.splits();
    Spectrum out(0.f, s.channels);
    for (int i = 0; i < s.channels; ++i) {
        double centre = s.bandCentre(i);
        out[i] = float(centre >= split[1] ? r : centre >= split[2] ? g : b);
    }
    return out;
}

}  // namespace

SigmoidCoefficients sigmoidCoefficients(double r, double g, double b) { return table().lookup(r, g, b); }

double sigmoidSpectrum(const SigmoidCoefficients& c, double nm) {
    double t = scaled(nm);
    return sigmoid((c[0] * t + c[1]) * t + c[2]);
}

Spectrum spectrumFromRgb(double r, double g, double b) {
    const SpectralSampling& s = spectralSampling();
    if (s.isRgb()) return Spectrum(float(r), float(g), float(b));
    if (r == g && g == b) return Spectrum(float(r));
    if (!(std::min({r, g, b}) >= 0) || !std::isfinite(r + g + b)) return boxSpectrum(r, g, b, s);
    double peak = std::max({r, g, b});
    double scale = peak > 1 ? 2 * peak : 1;
    SigmoidCoefficients c = sigmoidCoefficients(r / scale, g / scale, b / scale);
    // Band averages by the midpoint rule, a sample per 10 nm or less of each band.
    Spectrum out(0.f, s.channels);
    for (int i = 0; i < s.channels; ++i) {
        auto band = s.band(i);
        int n = std::max(1, int(std::ceil((band[0] - band[1]) / 10 - 1e-9)));
        double sum = 0;
        for (int q = 0; q < n; ++q) sum += sigmoidSpectrum(c, band[0] + (q + 0.5) * (band[1] - band[0]) / n);
        out[i] = float(scale * sum / n);
    }
    return out;
}

}  // namespace brume
