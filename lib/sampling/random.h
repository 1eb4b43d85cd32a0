// Random numbers for Monte Carlo: PCG32 streams seeded per ray, so results do not depend on which thread
// traced which ray, and (0,2)-sequence points for stratified 2-D sampling.
#pragma once
#include <cstdint>

namespace brume {

// PCG32 (O'Neill 2014): small state, good statistics, independent streams.
class Random {
public:
    explicit Random(uint64_t seed = 0, uint64_t stream = 0) { seedWith(seed, stream); }
    void seedWith(uint64_t seed, uint64_t stream) {
        state_ = 0;
        inc_ = (stream << 1u) | 1u;
        next();
        state_ += seed;
        next();
    }
    uint32_t next() {
        uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((-rot) & 31));
    }
    // Uniform in [0, 1).
    double uniform() { return (next() >> 8) * 0x1p-24 + (next() >> 11) * 0x1p-45; }

private:
    uint64_t state_, inc_;
};

// A 64-bit hash of several integers (SplitMix64 finaliser), for per-ray seeds.
inline uint64_t mixBits(uint64_t v) {
    v ^= v >> 31;
    v *= 0x7fb5d329728ea185ULL;
    v ^= v >> 27;
    v *= 0x81dadef4bc2dd44dULL;
    v ^= v >> 33;
    return v;
}

// Point i of the first two dimensions of the Sobol sequence (a (0,2)-sequence: every power-of-two prefix
// is stratified in both dimensions), XOR-scrambled by `scramble` so that different pixels get
// decorrelated sets with the same stratification.
inline void sobol2D(uint32_t i, uint64_t scramble, double& u, double& v) {
    uint32_t x = 0, y = 0;
    for (uint32_t c = 1u << 31, k = i; k; k >>= 1, c >>= 1)
        if (k & 1) x ^= c;
    for (uint32_t c = 1u << 31, k = i; k; k >>= 1, c ^= c >> 1)
        if (k & 1) y ^= c;
    x ^= static_cast<uint32_t>(scramble);
    y ^= static_cast<uint32_t>(scramble >> 32);
    u = x * 0x1p-32;
    v = y * 0x1p-32;
}

}  // namespace brume
