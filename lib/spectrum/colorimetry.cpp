#include "spectrum/colorimetry.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "spectrum/cie_tables.h"

namespace brume {

namespace {

Color3 whiteXyz(Chromaticity w) { return {w.x / w.y, 1, (1 - w.x - w.y) / w.y}; }

// The "sharp" sensor space of von Kries adaptation (Süsstrunk, Holm, Finlayson 2001), Radiance's vkmat.
constexpr Matrix3 kSharp{{{1.2694, -0.0988, -0.1706}, {-0.8364, 1.8006, 0.0357}, {0.0297, -0.0315, 1.0018}}};

// XYZ seen under white `from` to XYZ seen under white `to`.
Matrix3 adaptation(Chromaticity from, Chromaticity to) {
    Color3 a = kSharp * whiteXyz(from), b = kSharp * whiteXyz(to);
    Matrix3 scale{};
    for (int i = 0; i < 3; ++i) scale[i][i] = b[i] / a[i];
    return inverse(kSharp) * scale * kSharp;
}

double share(const TabulatedSpectrum& f, std::array<double, 2> band) {
    return f.integral(band[1], band[0]) / f.integral(f.first, f.last());
}

std::vector<double> weights(const TabulatedSpectrum& f, const SpectralSampling& s) {
    std::vector<double> w(size_t(s.channels));
    for (int i = 0; i < s.channels; ++i) w[size_t(i)] = share(f, s.band(i));
    return w;
}

double dot(const std::vector<double>& w, const Spectrum& s) {
    double sum = 0;
    for (int i = 0; i < s.size(); ++i) sum += w[size_t(i)] * s[i];
    return sum;
}

double daylightIntegral(const TabulatedSpectrum& f) {
    const TabulatedSpectrum& d65 = illuminantD65();
    double sum = 0;
    for (double nm = f.first; nm <= f.last(); nm += 1) sum += f.at(nm) * d65.at(nm);
    return sum / f.integral(f.first, f.last());
}

}  // namespace

double determinant(const Matrix3& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Matrix3 inverse(const Matrix3& m) {
    double d = determinant(m);
    Matrix3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, e = (i + 2) % 3;
            r[i][j] = (m[a][c] * m[b][e] - m[a][e] * m[b][c]) / d;
        }
    return r;
}

Matrix3 operator*(const Matrix3& a, const Matrix3& b) {
    Matrix3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

bool validPrimaries(const Primaries& p) {
    for (Chromaticity c : {p.red, p.green, p.blue, p.white})
        if (!(c.x > 0 && c.y > 0 && c.x + c.y < 1)) return false;
    Matrix3 m{{{p.red.x, p.green.x, p.blue.x}, {p.red.y, p.green.y, p.blue.y}, {1, 1, 1}}};
    if (std::abs(determinant(m)) < 1e-6) return false;
    Color3 s = inverse(m) * Color3{p.white.x, p.white.y, 1};  // the white as a mix of the primaries
    return s[0] > 0 && s[1] > 0 && s[2] > 0;
}

Color3 operator*(const Matrix3& m, const Color3& c) {
    return {m[0][0] * c[0] + m[0][1] * c[1] + m[0][2] * c[2], m[1][0] * c[0] + m[1][1] * c[1] + m[1][2] * c[2],
            m[2][0] * c[0] + m[2][1] * c[1] + m[2][2] * c[2]};
}

Matrix3 rgbToXyz(const Primaries& p) {
    Matrix3 m;
    const Chromaticity c[3] = {p.red, p.green, p.blue};
    for (int j = 0; j < 3; ++j) {
        Color3 col = whiteXyz(c[j]);
        for (int i = 0; i < 3; ++i) m[i][j] = col[i];
    }
    Color3 scale = inverse(m) * whiteXyz(p.white);  // so that RGB (1,1,1) is the white with Y = 1
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] *= scale[j];
    return m;
}

Matrix3 xyzToRgb(const Primaries& p) {
    return inverse(rgbToXyz(p)) * adaptation(kRadiancePrimaries.white, p.white);
}

ObserverWeights observerWeightsOf(const SpectralSampling& s) {
    return {weights(cieX(), s), weights(cieY(), s), weights(cieZ(), s), weights(scotopicEfficiency(), s),
            weights(melanopicEfficiency(), s), daylightIntegral(cieY()) / daylightIntegral(melanopicEfficiency())};
}

namespace {

std::once_flag gMade;
std::atomic<bool> gAreMade{false};
ObserverWeights gWeights;

}  // namespace

const ObserverWeights& observerWeights() {
    std::call_once(gMade, [] {
        gWeights = observerWeightsOf(spectralSampling());
        gAreMade = true;
    });
    return gWeights;
}

// RGB runs rarely need the weights (scotopic and melanopic outputs): their first use makes them, and spares
// the others parsing the CIE tables.
void remakeObserverWeights() {
    if (gAreMade) gWeights = observerWeightsOf(spectralSampling());
    else if (!spectralSampling().isRgb()) observerWeights();
}

Color3 toXyz(const Spectrum& s) {
    static const Matrix3 radianceToXyz = rgbToXyz(kRadiancePrimaries);
    if (s.size() == 3) return radianceToXyz * Color3{s[0], s[1], s[2]};
    const ObserverWeights& w = observerWeights();
    return {dot(w.x, s), dot(w.y, s), dot(w.z, s)};
}

Color3 toRgb(const Spectrum& s, const Primaries& p) {
    if (s.size() == 3 && p == kRadiancePrimaries) return {s[0], s[1], s[2]};
    return xyzToClippedRgb(toXyz(s), p);
}

Color3 xyzToClippedRgb(const Color3& xyz, const Primaries& p) {
    // Radiance's own primaries convert every value written in bands: their matrix is made once.
    static const Matrix3 xyzToRadiance = xyzToRgb(kRadiancePrimaries);
    Color3 rgb = (p == kRadiancePrimaries ? xyzToRadiance : xyzToRgb(p)) * xyz;
    double y = xyz[1];
    if (y < 0) return {0, 0, 0};
    double keep = 1;  // of the colour's difference from its grey, just enough to bring negatives to 0
    for (double c : rgb)
        if (c < 0) keep = std::min(keep, y / (y - c));
    for (double& c : rgb) c = std::max(0.0, keep * c + (1 - keep) * y);  // (the negatives' 0, rounded, may be −1e−18)
    return rgb;
}

Color3 xyzToRgbWithoutGrey(const Color3& xyz) {
    static const Matrix3 xyzToRadiance = xyzToRgb(kRadiancePrimaries), radianceToXyz = rgbToXyz(kRadiancePrimaries);
    Color3 rgb = xyzToRadiance * xyz;
    double y = 0;
    for (int c = 0; c < 3; ++c) y += radianceToXyz[1][size_t(c)] * (rgb[size_t(c)] = std::max(0.0, rgb[size_t(c)]));
    if (!(y > 0) || !(xyz[1] > 0)) return {0, 0, 0};
    for (double& c : rgb) c *= xyz[1] / y;
    return rgb;
}

double photopic(const Spectrum& s) {
    if (s.size() == 3) return brightnessOf(s, 3);
    return dot(observerWeights().y, s);
}

double scotopic(const Spectrum& s) { return dot(observerWeights().scotopic, s); }

double melanopic(const Spectrum& s) { return dot(observerWeights().melanopic, s); }

double melanopicDaylight(const Spectrum& s) { return melanopic(s) * observerWeights().melanopicToDaylight; }

double spectralRadiancePerValue() {
    constexpr double kMaximumEfficacy = 683.002;  // lm/W at 555 nm (CIE 15)
    return 179 / (kMaximumEfficacy * cieY().integral(cieY().first, cieY().last()));
}

}  // namespace brume
