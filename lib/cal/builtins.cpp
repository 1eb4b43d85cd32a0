#include "cal/builtins.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "cal/channels.h"
#include "cal/noise.h"
#include "util/error.h"

namespace brume::cal {

namespace {

using std::numbers::pi;

double arg(const RayInput& ray, int i) { return patternArgument(i, ray.args); }

double extreme(const double* a, int n, bool wantMax) {
    double v = a[0];
    for (int i = 1; i < n; ++i) v = wantMax ? std::max(v, a[i]) : std::min(v, a[i]);
    return v;
}

// Radiance's source_corr(value, kind) (rt/func.c): the photometric correction ies2rad's output applies
// through source.cal. A1 scales the value when there are two or more real arguments; A2..A4 are the
// emitter's size in metres. Kinds: 0 none, 1 flat, 2 box, 3 box seen from nearby, 4 cylinder.
double sourceCorrection(const double* a, int, const RayInput& ray) {
    const double* ch = ray.channels;
    double value = ray.args.size() > 1 ? a[0] * arg(ray, 1) : a[0];
    if (value <= 0) return 0;
    auto need = [&](size_t n) {
        if (ray.args.size() < n) throw Error("source_corr(): missing real argument(s)");
    };
    switch (static_cast<int>(std::floor(a[1] + .5))) {
        case 0:
            return value;
        case 1:
            return value / ch[Rdot];
        case 2:
            need(4);
            return value /
                   (std::abs(ch[Dx]) * arg(ray, 3) * arg(ray, 4) + std::abs(ch[Dy]) * arg(ray, 2) * arg(ray, 4) +
                    std::abs(ch[Dz]) * arg(ray, 2) * arg(ray, 3));
        case 3: {
            need(4);
            // The box's faces projected towards the point the shadow ray left from.
            double projected = 0;
            for (int i = 0; i < 3; ++i) {
                double d = std::abs(ch[Px + i] - ch[Dx + i] * ch[Ts]) - arg(ray, 2 + i) * .5;
                if (d > 0) projected += d * arg(ray, 2 + (i + 1) % 3) * arg(ray, 2 + (i + 2) % 3);
            }
            return value * ch[Ts] / projected;
        }
        case 4: {
            need(3);
            double cosine = std::min(ch[Dz], 1 - 1e-7);
            double diameter = arg(ray, 2), height = arg(ray, 3);
            return value / (diameter * height * std::sqrt(1 - cosine * cosine) +
                            .25 * pi * diameter * diameter * std::abs(cosine));
        }
        default:
            throw Error("illegal second argument to source_corr()");
    }
}

// Radiance's source_theta: the angle in degrees between the light leaving the source (-D) and the
// source's -z axis, acos(Dz).
double sourceTheta(const double*, int, const RayInput& ray) {
    double dz = ray.channels[Dz];
    return dz >= 1 ? 0 : dz <= -1 ? 180 : 180 / pi * std::acos(dz);
}

// Radiance's source_phi(symmetry): the azimuth of the direction from the source, in degrees from +x
// towards +y, folded for quadrant (90) or bilateral (180) symmetry, or not (360).
double sourcePhi(const double* a, int, const RayInput& ray) {
    double phi = 180 / pi * std::atan2(-ray.channels[Dy], -ray.channels[Dx]);
    if (phi < 0) phi += 360;
    switch (static_cast<int>(std::floor(a[0] + .5))) {
        case 90:
            if (phi >= 180) phi -= 180;
            return phi < 90 ? phi : 180 - phi;
        case 180:
            return phi < 180 ? phi : 360 - phi;
        case 360:
            return phi;
        default:
            throw Error("bad argument to source_phi()");
    }
}

// Radiance's noise3x/y/z are evaluated together at one point (a texture's three components), so the last
// point's gradient is kept, per thread.
double noiseComponent(const double* a, int component) {
    thread_local double last[3] = {NAN, NAN, NAN};
    thread_local std::array<double, 4> values;
    if (a[0] != last[0] || a[1] != last[1] || a[2] != last[2]) {
        values = perlinNoiseAndGradient(a[0], a[1], a[2]);
        std::copy(a, a + 3, last);
    }
    return values[component];
}

template <double (*F)(double)>
double unary(const double* a, int, const RayInput&) {
    return F(a[0]);
}

double sqrtOf(double x) { return std::sqrt(x); }
double sinOf(double x) { return std::sin(x); }
double cosOf(double x) { return std::cos(x); }
double tanOf(double x) { return std::tan(x); }
double asinOf(double x) { return std::asin(x); }
double acosOf(double x) { return std::acos(x); }
double atanOf(double x) { return std::atan(x); }
double expOf(double x) { return std::exp(x); }
double logOf(double x) { return std::log(x); }
double log10Of(double x) { return std::log10(x); }
double floorOf(double x) { return std::floor(x); }
double ceilOf(double x) { return std::ceil(x); }
double erfOf(double x) { return std::erf(x); }
double erfcOf(double x) { return std::erfc(x); }

// Sorted by name for the binary search in findBuiltin.
constexpr Builtin kBuiltins[] = {
    {"acos", 1, false, false, unary<acosOf>},
    {"arg", 1, false, true, [](const double* a, int, const RayInput& r) { return patternArgument(a[0], r.args); }},
    {"asin", 1, false, false, unary<asinOf>},
    {"atan", 1, false, false, unary<atanOf>},
    {"atan2", 2, false, false, [](const double* a, int, const RayInput&) { return std::atan2(a[0], a[1]); }},
    {"ceil", 1, false, false, unary<ceilOf>},
    {"cos", 1, false, false, unary<cosOf>},
    {"erf", 1, false, false, unary<erfOf>},
    {"erfc", 1, false, false, unary<erfcOf>},
    {"exp", 1, false, false, unary<expOf>},
    {"floor", 1, false, false, unary<floorOf>},
    {"fnoise3", 3, false, false, [](const double* a, int, const RayInput&) { return fractalNoise(a[0], a[1], a[2]); }},
    {"if", 3, false, false, [](const double* a, int, const RayInput&) { return a[0] > 0 ? a[1] : a[2]; }},
    {"log", 1, false, false, unary<logOf>},
    {"log10", 1, false, false, unary<log10Of>},
    {"max", 1, true, false, [](const double* a, int n, const RayInput&) { return extreme(a, n, true); }},
    {"min", 1, true, false, [](const double* a, int n, const RayInput&) { return extreme(a, n, false); }},
    {"noise3", 3, false, false, [](const double* a, int, const RayInput&) { return noiseComponent(a, 0); }},
    {"noise3x", 3, false, false, [](const double* a, int, const RayInput&) { return noiseComponent(a, 1); }},
    {"noise3y", 3, false, false, [](const double* a, int, const RayInput&) { return noiseComponent(a, 2); }},
    {"noise3z", 3, false, false, [](const double* a, int, const RayInput&) { return noiseComponent(a, 3); }},
    {"rand", 1, false, false, [](const double* a, int, const RayInput&) { return hashRandom(a[0]); }},
    {"select", 1, true, false,
     [](const double* a, int n, const RayInput&) {
         int k = selectIndex(a[0], n - 1);
         return k < 0 ? NAN : k == 0 ? n - 1 : a[k];
     }},
    {"sin", 1, false, false, unary<sinOf>},
    {"source_corr", 2, false, true, sourceCorrection},
    {"source_phi", 1, false, true, sourcePhi},
    {"source_theta", 1, false, true, sourceTheta},
    {"sqrt", 1, false, false, unary<sqrtOf>},
    {"tan", 1, false, false, unary<tanOf>},
};

}  // namespace

const Builtin* findBuiltin(std::string_view name) {
    auto it = std::lower_bound(std::begin(kBuiltins), std::end(kBuiltins), name,
                               [](const Builtin& b, std::string_view n) { return b.name < n; });
    return it != std::end(kBuiltins) && it->name == name ? it : nullptr;
}

double patternArgument(double n, std::span<const double> args) {
    double k = std::floor(n + .5);
    if (k < 1) return static_cast<double>(args.size());
    if (!(k <= static_cast<double>(args.size())))
        throw Error(k < 1e9 ? "missing real argument " + std::to_string(static_cast<long long>(k))
                            : std::string("arg(): argument number out of range"));
    return args[static_cast<size_t>(k) - 1];
}

int selectIndex(double n, int choices) {
    if (!(n >= -.5 && n + .5 < choices + 1)) return -1;
    return static_cast<int>(n + .5);
}

}  // namespace brume::cal
