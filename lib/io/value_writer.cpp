#include "io/value_writer.h"

#include <algorithm>
#include <cmath>

namespace brume {

namespace {
constexpr double kMiss = 1e10;  // Radiance's FHUGE, printed for lengths of rays that hit nothing
const std::string kLetters = "odvVwWlLcpnNsmMrxRX~";

double length(double d) { return std::isfinite(d) ? d : kMiss; }
}  // namespace

void encodeCommonExponent(const double* v, int n, unsigned char* out) {
    double d = *std::max_element(v, v + n);
    if (!(d > 1e-32)) {
        std::fill_n(out, n + 1, 0);
        return;
    }
    int e;
    double f = std::frexp(d, &e) * 256.0 / d;
    for (int i = 0; i < n; ++i) out[i] = v[i] > 0 ? static_cast<unsigned char>(v[i] * f) : 0;
    out[n] = static_cast<unsigned char>(e + 128);
}

void encodeRgbe(float r, float g, float b, unsigned char out[4]) {
    double v[3] = {r, g, b};
    encodeCommonExponent(v, 3, out);
}

ValueWriter::ValueWriter(std::FILE* out, const std::string& spec, char format, const Scene& scene,
                         const ColorOutput& output)
    : out_(out), format_(format), scene_(scene), output_(output) {
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
    if (format_ == 'c' && output_.components() < 3) throw Error("color format incompatible with -pY, -pS, -pM, -pA");
}

int ValueWriter::components() const {
    if (tracing()) return 0;
    int n = 0;
    for (char c : perRay_) {
        if (std::string("vVWrx").find(c) != std::string::npos) n += output_.components();
        else if (std::string("odpnN").find(c) != std::string::npos) n += 3;
        else if (std::string("wlLRX").find(c) != std::string::npos) n += 1;
        else if (c == 'c') n += 2;
    }
    return n;
}

std::string ValueWriter::formatName() const {
    switch (format_) {
        case 'f': return "float";
        case 'd': return "double";
        case 'c':
            if (output_.kind == ColorOutput::Kind::Spectral && output_.components() > 3) return "Radiance_spectra";
            return output_.kind == ColorOutput::Kind::Xyz ? "32-bit_rle_xyze" : "32-bit_rle_rgbe";
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
    double v[Spectrum::kMaxChannels];
    output_.convert(c, v);
    int n = output_.components();
    if (format_ == 'c') {
        unsigned char bytes[Spectrum::kMaxChannels + 1];
        encodeCommonExponent(v, n, bytes);
        std::fwrite(bytes, 1, size_t(n) + 1, out_);
        return;
    }
    reals(v, n);
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
