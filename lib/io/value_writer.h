// rtrace's output stream: the header, and per ray the fields its -o letters ask for, in ASCII (each value
// "%e\t", a newline per ray), native floats or doubles, or Radiance's common-exponent bytes (-fc: RGBE, XYZE,
// or N mantissas and an exponent for spectra), byte for byte as Radiance. Colours as `output` says.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "io/ray_record.h"
#include "scene/scene.h"
#include "spectrum/color_output.h"

namespace brume {

struct OutputRay {
    dvec3 org, dir;
    const RayRecord* record;
};

class ValueWriter {
public:
    // Throws Error for an unknown letter or a format that cannot carry the fields (-fc).
    ValueWriter(std::FILE* out, const std::string& spec, char format, const Scene& scene,
                const ColorOutput& output = {});
    // Number of values per ray (the header's NCOMP); 0 in trace mode, as Radiance.
    int components() const;
    // "FORMAT=..." value for the header.
    std::string formatName() const;
    // Trace mode (-ot...): every ray of each tree is printed; -oT adds shadow rays.
    bool tracing() const { return !traced_.empty(); }
    bool tracesShadowRays() const { return shadowRays_; }
    // The per-ray fields (letters before any t/T) of one input ray.
    void write(const OutputRay& ray);
    // The trace lines of one input ray's tree: one tab per depth, then the letters after t/T.
    void writeTree(const RayTree& tree);

private:
    void fields(const std::string& spec, const OutputRay& ray);
    void reals(const double* v, int n);
    void real(double v);
    void color(const Spectrum& c);
    void text(const std::string& s);
    std::string objectName(int object) const;

    std::FILE* out_;
    std::string perRay_, traced_;
    bool shadowRays_ = false;
    char format_;
    const Scene& scene_;
    ColorOutput output_;
};

// Radiance's RGBE: a shared exponent byte and three 8-bit mantissas (Ward, Graphics Gems II).
void encodeRgbe(float r, float g, float b, unsigned char out[4]);
// The same for n values (Radiance's spectral SCOLR): n mantissas, then the exponent byte.
void encodeCommonExponent(const double* v, int n, unsigned char* out);

}  // namespace brume
