// Values of light as spectra of runtime length: 3 channels are Radiance's RGB, more are wavelength bands
// (set by -cs). Storage is inline with a fixed capacity, but copies and arithmetic touch only the
// channels in use, so RGB pays for 3 floats, not for the capacity.
#pragma once
#include <algorithm>
#include <cassert>
#include <cmath>
#include <type_traits>

namespace brume {

class Spectrum {
public:
    static constexpr int kMaxChannels = 96;

    // The channel count every Spectrum made without an explicit count gets (3 until -cs changes it), and
    // for spectra of more than 3 bands their weights in brightness() (photopic, summing to 1;
    // spectral_sampling.h sets both).
    static int defaultChannels() { return sChannels; }
    static void setDefaultChannels(int n, const float* brightnessWeights = nullptr) {
        assert(n > 0 && n <= kMaxChannels);
        sChannels = n;
        sWeighted = brightnessWeights != nullptr;
        if (sWeighted) std::copy_n(brightnessWeights, n, sWeights);
    }
    // The brightness weights of n bands, or nullptr when there are none (the bands are then equal).
    static const float* brightnessWeights(int n) { return sWeighted && n == sChannels ? sWeights : nullptr; }

    Spectrum() : Spectrum(0.f) {}
    explicit Spectrum(float v, int n = sChannels) : n_(n) { std::fill_n(v_, n_, v); }
    Spectrum(float r, float g, float b) : n_(3) { v_[0] = r, v_[1] = g, v_[2] = b; }
    Spectrum(const Spectrum& o) : n_(o.n_) { copyFrom(o); }
    Spectrum& operator=(const Spectrum& o) {
        n_ = o.n_;
        copyFrom(o);
        return *this;
    }

    int size() const { return n_; }
    float operator[](int i) const { return v_[i]; }
    float& operator[](int i) { return v_[i]; }

    Spectrum& operator+=(const Spectrum& o) { return apply(o, [](float& a, float b) { a += b; }); }
    Spectrum& operator-=(const Spectrum& o) { return apply(o, [](float& a, float b) { a -= b; }); }
    Spectrum& operator*=(const Spectrum& o) { return apply(o, [](float& a, float b) { a *= b; }); }
    Spectrum& operator/=(const Spectrum& o) {
        return apply(o, [](float& a, float b) { a = b != 0.f ? a / b : 0.f; });
    }
    // Adds s to every channel.
    Spectrum& operator+=(float s) {
        for (int i = 0; i < n_; ++i) v_[i] += s;
        return *this;
    }
    // Adds a·b·s, as *this += a * b * s would, without that expression's temporaries (each one a Spectrum of
    // full capacity).
    Spectrum& addProduct(const Spectrum& a, const Spectrum& b, float s) {
        assert(a.n_ == n_ && b.n_ == n_);
        for (int i = 0; i < n_; ++i) v_[i] += a.v_[i] * b.v_[i] * s;
        return *this;
    }
    Spectrum& operator*=(float s) {
        for (int i = 0; i < n_; ++i) v_[i] *= s;
        return *this;
    }
    friend Spectrum operator+(Spectrum a, const Spectrum& b) { return a += b; }
    friend Spectrum operator-(Spectrum a, const Spectrum& b) { return a -= b; }
    friend Spectrum operator*(Spectrum a, const Spectrum& b) { return a *= b; }
    friend Spectrum operator/(Spectrum a, const Spectrum& b) { return a /= b; }
    friend Spectrum operator*(Spectrum a, float s) { return a *= s; }
    friend Spectrum operator*(float s, Spectrum a) { return a *= s; }

    bool isBlack() const { return std::all_of(v_, v_ + n_, [](float x) { return x == 0.f; }); }
    float maxValue() const { return *std::max_element(v_, v_ + n_); }
    float average() const {
        float s = 0;
        for (int i = 0; i < n_; ++i) s += v_[i];
        return s / n_;
    }
    // Replaces NaN and infinite channels by zero: one bad sample must not poison a pixel or a sum.
    Spectrum& clampFinite() {
        for (int i = 0; i < n_; ++i)
            if (!std::isfinite(v_[i])) v_[i] = 0.f;
        return *this;
    }

private:
    // RGB inline: a library call per copy would cost more than the copy.
    void copyFrom(const Spectrum& o) {
        if (n_ == 3) v_[0] = o.v_[0], v_[1] = o.v_[1], v_[2] = o.v_[2];
        else std::copy_n(o.v_, n_, v_);
    }
    template <class F>
    Spectrum& apply(const Spectrum& o, F f) {
        assert(o.n_ == n_);
        for (int i = 0; i < n_; ++i) f(v_[i], o.v_[i]);
        return *this;
    }
    inline static int sChannels = 3;
    inline static bool sWeighted = false;
    inline static float sWeights[kMaxChannels] = {};
    int n_;
    float v_[kMaxChannels];
};

// Σ w[i]·v[i] over n channels (w null: Σ v[i]), in four running sums: one chain of additions would wait on
// each one, a cost that shows at 81 bands.
template <class T, class Channels>
T weightedSum(const Channels& v, const float* w, int n) {
    T s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    int i = 0;
    if (w) {
        for (; i + 4 <= n; i += 4)
            s0 += T(w[i]) * v[i], s1 += T(w[i + 1]) * v[i + 1], s2 += T(w[i + 2]) * v[i + 2], s3 += T(w[i + 3]) * v[i + 3];
        for (; i < n; ++i) s0 += T(w[i]) * v[i];
    } else {
        for (; i + 4 <= n; i += 4) s0 += v[i], s1 += v[i + 1], s2 += v[i + 2], s3 += v[i + 3];
        for (; i < n; ++i) s0 += v[i];
    }
    return (s0 + s1) + (s2 + s3);
}

// Radiance's luminance weights of its RGB primaries (the "bright" of color.h): Y = .265 R + .670 G + .065 B;
// for spectral bands their photopic weights (the mean without any). For any n channels v[0 … n-1] (a
// spectrum, or values stored apart). A grey of value g has brightness g either way.
template <class Channels>
auto brightnessOf(const Channels& v, int n) {
    using T = std::decay_t<decltype(v[0])>;
    if (n == 3) return T(0.265) * v[0] + T(0.670) * v[1] + T(0.065) * v[2];
    const float* w = Spectrum::brightnessWeights(n);
    T sum = weightedSum<T>(v, w, n);
    return w ? sum : sum / T(n);
}

inline float brightness(const Spectrum& s) { return brightnessOf(s, s.size()); }

}  // namespace brume
