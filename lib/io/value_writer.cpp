#include "io/value_writer.h"

#include <cmath>

namespace brume {

namespace {
constexpr double kMiss = 1e10;  // Radiance's FHUGE, printed for lengths of rays that hit nothing
const std::string kLetters = "odvVwWlLcpnNsmMrxRX~";

double length(double d) { return std::isfinite(d) ? d : kMiss; }
}  // namespace

void encodeRgbe(float r, float g, float b, unsigned char out[4]) {
    double d = std::max({r, g, b});
    if (d <= 1e-32) {
        out[0] = out[1] = out[2] = out[3] = 0;
        return;
    }
    int e;
    double m = std::frexp(d, &e);
    double f = m * 256.0 / d;
    out[0] = r > 0 ? static_cast<unsigned char>(r * f) : 0;
    out[1] = g > 0 ? static_cast<unsigned char>(g * f) : 0;
    out[2] = b > 0 ? static_cast<unsigned char>(b * f) : 0;
    out[3] = static_cast<unsigned char>(e + 128);
}

ValueWriter::ValueWriter(std::FILE* out, const std::string& spec, char format, const Scene& scene)
    : out_(out), format_(format), scene_(scene) {
    if (spec.empty()) throw Error("empty output specification");
    std::string* into = &perRay_;
    for (size_t i = 0; i < spec.size(); ++i) {
        char c = spec[i];
        if (c == 't' || c == 'T') {
            if (i + 1 < spec.size()) into = &traced_, shadowRays_ = shadowRays_ || c == 'T';
            continue;  // a final t does nothing, as in Radiance
        }
        if (kLetters.find(c) == std::string::npos) throw Error(std::string("unrecognized output option '") + c + "'");
        *into += c;
    }
    if (format_ == 'c' && (tracing() || (perRay_ != "v" && perRay_ != "r" && perRay_ != "x")))
        throw Error("color format only with -ov, -or, -ox");
}

int ValueWriter::components() const {
    if (tracing()) return 0;
    int n = 0;
    for (char c : perRay_) {
        if (std::string("odvVWpnNrx").find(c) != std::string::npos) n += 3;
        else if (std::string("wlLRX").find(c) != std::string::npos) n += 1;
        else if (c == 'c') n += 2;
    }
    return n;
}

std::string ValueWriter::formatName() const {
    switch (format_) {
        case 'f': return "float";
        case 'd': return "double";
        case 'c': return "32-bit_rle_rgbe";
        default: return "ascii";
    }
}

void ValueWriter::reals(const double* v, int n) {
    for (int i = 0; i < n; ++i) {
        if (format_ == 'f') {
            float f = static_cast<float>(v[i]);
            std::fwrite(&f, sizeof f, 1, out_);
        } else if (format_ == 'd') {
            std::fwrite(&v[i], sizeof(double), 1, out_);
        } else {
            std::fprintf(out_, "%e\t", v[i]);
        }
    }
}

void ValueWriter::real(double v) { reals(&v, 1); }

void ValueWriter::color(const Spectrum& c) {
    if (format_ == 'c') {
        unsigned char rgbe[4];
        encodeRgbe(c[0], c[1], c[2], rgbe);
        std::fwrite(rgbe, 1, 4, out_);
        return;
    }
    // Radiance keeps colours in single precision; print exactly those values.
    double v[3] = {double(c[0]), double(c[1]), double(c[2])};
    reals(v, 3);
}

void ValueWriter::text(const std::string& s) { std::fprintf(out_, "%s\t", s.c_str()); }

std::string ValueWriter::objectName(int object) const { return object < 0 ? "*" : scene_.objects[object].name; }

void ValueWriter::write(const OutputRay& ray) {
    fields(perRay_, ray);
    if (format_ == 'a' && !perRay_.empty()) std::fputc('\n', out_);
}

void ValueWriter::writeTree(const RayTree& tree) {
    for (const TracedRay& t : tree.rays) {
        for (int i = 0; i < t.depth; ++i) std::fputc('\t', out_);
        fields(traced_, {t.org, t.dir, &t.record});
        if (format_ == 'a') std::fputc('\n', out_);
    }
}

void ValueWriter::fields(const std::string& spec, const OutputRay& ray) {
    const RayRecord& r = *ray.record;
    bool hit = r.surfaceObject >= 0;       // a surface, or a source at infinity
    bool local = std::isfinite(r.firstLength);
    for (char c : spec) {
        switch (c) {
            case 'o': reals(&ray.org.x, 3); break;
            case 'd': reals(&ray.dir.x, 3); break;
            case 'v':
            case 'V': color(r.value); break;
            case 'W': color(Spectrum(1.f)); break;
            case 'w': real(1); break;
            case 'l': real(length(r.effectiveLength)); break;
            case 'L':
            case 'X': real(length(r.firstLength)); break;
            case 'R': real(length(r.mirroredLength)); break;
            case 'c':
                real(r.uv.x), real(r.uv.y);
                break;
            case 'p': reals(local ? &r.point.x : &ray.org.x, 3); break;
            case 'n':
            case 'N': {
                dvec3 n = hit ? (c == 'n' ? r.normal : r.surfaceNormal) : dvec3(0);
                reals(&n.x, 3);
                break;
            }
            case 's': text(objectName(r.surfaceObject)); break;
            // m: the surface's own modifier (a pattern, say); M: the material its modifiers end in.
            case 'm': text(hit && r.surfaceObject >= 0 ? objectName(scene_.objects[r.surfaceObject].modifier) : "*"); break;
            case 'M': text(hit ? objectName(r.modifierObject) : "*"); break;
            case 'r': color(r.mirrored); break;
            case 'x': color(r.value - r.mirrored); break;
            case '~': text("~"); break;
        }
    }
}

}  // namespace brume
