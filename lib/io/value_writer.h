// rtrace's output stream: the header, and per ray the fields its -o letters ask for, in ASCII (each value
// "%e\t", a newline per ray), native floats or doubles, or 4-byte RGBE (-fc), byte for byte as Radiance.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "integrator/integrator.h"

namespace brume {

struct OutputRay {
    dvec3 org, dir;
    const RayRecord* record;
};

class ValueWriter {
public:
    // Throws Error for an unknown letter or a format that cannot carry the fields (-fc).
    ValueWriter(std::FILE* out, const std::string& spec, char format, const Scene& scene);
    // Number of values per ray (the header's NCOMP).
    int components() const;
    // "FORMAT=..." value for the header.
    std::string formatName() const;
    void write(const OutputRay& ray);

private:
    void reals(const double* v, int n);
    void color(const Spectrum& c);
    void text(const std::string& s);
    std::string objectName(int object) const;

    std::FILE* out_;
    std::string spec_;
    char format_;
    const Scene& scene_;
};

// Radiance's RGBE: a shared exponent byte and three 8-bit mantissas (Ward, Graphics Gems II).
void encodeRgbe(float r, float g, float b, unsigned char out[4]);

}  // namespace brume
