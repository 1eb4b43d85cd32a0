#include "cal/noise.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace brume::cal {

namespace {

// Brume's own lattice: a fixed shuffle of 0..255 (Fisher-Yates driven by Knuth's MMIX generator).
constexpr std::array<uint8_t, 256> makePermutation() {
    std::array<uint8_t, 256> p{};
    for (int i = 0; i < 256; ++i) p[i] = static_cast<uint8_t>(i);
    uint64_t state = 0x2545F4914F6CDD1DULL;
    for (int i = 255; i > 0; --i) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        std::swap(p[i], p[(state >> 33) % static_cast<uint64_t>(i + 1)]);
    }
    return p;
}
constexpr std::array<uint8_t, 256> kPermutation = makePermutation();

// Perlin (2002): the 12 vectors to the edge midpoints of a cube, padded to 16 for a cheap index.
constexpr double kGradients[16][3] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {0, -1, 1}, {-1, 1, 0}, {0, -1, -1},
};

int latticeHash(int x, int y, int z) {
    return kPermutation[(kPermutation[(kPermutation[x & 255] + y) & 255] + z) & 255];
}

// Perlin's quintic 6t^5 - 15t^4 + 10t^3 and its derivative: continuous second derivatives.
double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
double fadeDerivative(double t) { return 30 * t * t * (t - 1) * (t - 1); }

// The lattice cell of x modulo 256 (the period of the permutation), safe for any finite x.
int cell(double floored) { return static_cast<int>(std::fmod(floored, 256.0)) & 255; }

// splitmix64's finaliser: every input bit affects every output bit.
uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

// The bits of an integral double, +0 and -0 alike.
uint64_t bits(double v) { return std::bit_cast<uint64_t>(v + 0.0); }

// A value in [-1, 1) at an integer lattice point, given as doubles so that no coordinate overflows.
double latticeValue(double x, double y, double z) {
    uint64_t h = mix(bits(x) + mix(bits(y) + mix(bits(z) + 0x9E3779B97F4A7C15ULL)));
    return static_cast<double>(h >> 11) * 0x1p-52 - 1;
}

double lerp(double t, double a, double b) { return a + t * (b - a); }

double valueNoise(double x, double y, double z) {
    double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    double u = fade(x - fx), v = fade(y - fy), w = fade(z - fz);
    auto at = [&](int i, int j, int k) { return latticeValue(fx + i, fy + j, fz + k); };
    return lerp(w, lerp(v, lerp(u, at(0, 0, 0), at(1, 0, 0)), lerp(u, at(0, 1, 0), at(1, 1, 0))),
                lerp(v, lerp(u, at(0, 0, 1), at(1, 0, 1)), lerp(u, at(0, 1, 1), at(1, 1, 1))));
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

std::array<double, 4> perlinNoiseAndGradient(double x, double y, double z) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return {kNaN, kNaN, kNaN, kNaN};
    const double floors[3] = {std::floor(x), std::floor(y), std::floor(z)};
    const double t[3] = {x - floors[0], y - floors[1], z - floors[2]};
    const int cells[3] = {cell(floors[0]), cell(floors[1]), cell(floors[2])};
    double s[3], ds[3];
    for (int i = 0; i < 3; ++i) {
        s[i] = fade(t[i]);
        ds[i] = fadeDerivative(t[i]);
    }
    // The value is the sum over the cell's 8 corners of weight * (gradient . offset); the gradient
    // follows by the product rule.
    std::array<double, 4> result{};
    for (int corner = 0; corner < 8; ++corner) {
        int b[3] = {corner & 1, corner >> 1 & 1, corner >> 2 & 1};
        const double* g = kGradients[latticeHash(cells[0] + b[0], cells[1] + b[1], cells[2] + b[2]) & 15];
        double w[3], dw[3], dot = 0;
        for (int i = 0; i < 3; ++i) {
            w[i] = b[i] ? s[i] : 1 - s[i];
            dw[i] = b[i] ? ds[i] : -ds[i];
            dot += g[i] * (t[i] - b[i]);
        }
        double weight = w[0] * w[1] * w[2];
        result[0] += weight * dot;
        result[1] += dw[0] * w[1] * w[2] * dot + weight * g[0];
        result[2] += w[0] * dw[1] * w[2] * dot + weight * g[1];
        result[3] += w[0] * w[1] * dw[2] * dot + weight * g[2];
    }
    return result;
}

double perlinNoise(double x, double y, double z) { return perlinNoiseAndGradient(x, y, z)[0]; }

double fractalNoise(double x, double y, double z) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return kNaN;
    constexpr int kOctaves = 11;
    // The scale gives the spread of Radiance's fnoise3 (standard deviation 0.33, extremes about 1.2).
    constexpr double kScale = 0.8;
    double sum = 0, amplitude = kScale, frequency = 1;
    for (int k = 0; k < kOctaves; ++k, amplitude *= 0.5, frequency *= 2)
        sum += amplitude * valueNoise(x * frequency, y * frequency, z * frequency);
    return sum;
}

// Radiance's formula, so that patterns and bins (reinhartb.cal's jitter) that use rand() draw what they draw
// in Radiance: the fraction of 1e5 over a fraction of a stretched x, shifted off zero.
double hashRandom(double x) {
    if (!std::isfinite(x)) return 0;
    x *= 1 / (1 + x * x) + 2.71828182845904;
    x += 0.785398163397447 - std::floor(x);
    x = 1e5 / x;
    return x - std::floor(x);
}

}  // namespace brume::cal
