#include "io/picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <istream>
#include <ostream>

#include "io/openexr_picture.h"
#include "io/resolution.h"
#include "util/error.h"
#include "util/header.h"

namespace brume {

namespace {

constexpr int kMinRunLength = 4;
// Radiance 6.1 writes shorter and longer scanlines flat (color.c MINELEN, MAXELEN); its reader tells the
// encodings apart by the (2, 2, length) mark alone, whatever the length.
constexpr int kMinEncodedLength = 17, kMaxEncodedLength = 0x7fff;

[[noreturn]] void bad(const std::string& name, const std::string& what) {
    throw Error(name + ": " + what);
}

// Radiance's common-exponent decoding of n mantissas and the exponent after them: each mantissa's middle
// value times 2^(e−136) (Ward, Graphics Gems II).
void decode(const unsigned char* c, float* values, int n = 3) {
    double f = c[n] == 0 ? 0 : std::ldexp(1.0, int(c[n]) - 136);
    for (int i = 0; i < n; ++i) values[i] = float((c[i] + 0.5) * f);
}

void encode(const float* rgb, unsigned char* c) {
    double d = std::max({rgb[0], rgb[1], rgb[2]});
    if (!(d > 1e-32) || !std::isfinite(d)) {
        std::memset(c, 0, 4);
        return;
    }
    int e;
    double f = std::frexp(d, &e) * 256.0 / d;
    for (int i = 0; i < 3; ++i) c[i] = rgb[i] > 0 ? (unsigned char)(rgb[i] * f) : 0;
    c[3] = (unsigned char)(e + 128);
}

int byte(std::istream& in, const std::string& name) {
    int c = in.get();
    if (c == EOF) bad(name, "truncated picture");
    return c;
}

// One scanline of n RGBE pixels, in the new run-length encoding, the old one, or flat.
void readScanline(std::istream& in, const std::string& name, std::vector<unsigned char>& line, int n) {
    line.assign(size_t(n) * 4, 0);
    unsigned char first[4];
    for (auto& b : first) b = (unsigned char)byte(in, name);
    if (first[0] == 2 && first[1] == 2 && !(first[2] & 0x80)) {
        if ((first[2] << 8 | first[3]) != n) bad(name, "scanline length mismatch");
        for (int component = 0; component < 4; ++component) {
            for (int x = 0; x < n;) {
                int count = byte(in, name);
                bool run = count > 128;
                if (run) count -= 128;
                if (count == 0 || x + count > n) bad(name, "bad run length");
                int value = run ? byte(in, name) : 0;
                for (int k = 0; k < count; ++k, ++x) line[size_t(x) * 4 + component] = (unsigned char)(run ? value : byte(in, name));
            }
        }
        return;
    }
    // Old encoding: (1,1,1,k) repeats the previous pixel k << shift times, consecutive repeats shifting by 8.
    int shift = 0;
    for (int x = 0; x < n;) {
        unsigned char c[4];
        if (x == 0) std::memcpy(c, first, 4);
        else for (auto& b : c) b = (unsigned char)byte(in, name);
        if (c[0] == 1 && c[1] == 1 && c[2] == 1) {
            if (x == 0) bad(name, "repeat before first pixel");
            if (shift > 16) bad(name, "bad run length");  // a scanline holds at most 2^20 pixels
            long count = long(c[3]) << shift;
            if (x + count > n) bad(name, "bad run length");
            for (long k = 0; k < count; ++k, ++x) std::memcpy(&line[size_t(x) * 4], &line[size_t(x - 1) * 4], 4);
            shift += 8;
            continue;
        }
        std::memcpy(&line[size_t(x) * 4], c, 4);
        ++x;
        shift = 0;
    }
}

Resolution readResolution(std::istream& in, const std::string& name) {
    std::string line;
    if (!std::getline(in, line)) bad(name, "missing resolution line");
    return parseResolution(line, name);
}

// Reads the header into p; returns its FORMAT= (RGBE without one, as Radiance assumes).
std::string readHeader(std::istream& in, const std::string& name, Picture& p) {
    std::string line, format = "32-bit_rle_rgbe";
    if (!std::getline(in, line) || line != "#?RADIANCE") bad(name, "not a Radiance picture");
    while (std::getline(in, line) && !line.empty()) {
        if (isHeaderVariable(line, "FORMAT=")) {
            format = line.substr(7);
            while (!format.empty() && std::isspace((unsigned char)format.back())) format.pop_back();
            continue;
        }
        p.header.push_back(line);
    }
    p.exposure = headerProduct(p.header, "EXPOSURE=");
    p.pixelAspect = headerProduct(p.header, "PIXASPECT=");
    if (!in) bad(name, "truncated header");
    if (!(p.pixelAspect > 0) || !(p.exposure > 0)) bad(name, "bad EXPOSURE= or PIXASPECT=");
    return format;
}

// The value of header line `name` ("NCOMP=6"), or "" without one.
std::string headerValue(const std::vector<std::string>& header, std::string_view name) {
    for (const std::string& line : header)
        if (isHeaderVariable(line, name)) return line.substr(name.size());
    return "";
}

}  // namespace

Picture readRadiancePicture(std::istream& in, const std::string& name) {
    Picture p;
    std::string format = readHeader(in, name, p);
    if (format != "32-bit_rle_rgbe" && format != "32-bit_rle_xyze") bad(name, "unsupported picture format " + format);
    p.xyz = format == "32-bit_rle_xyze";
    Resolution o = readResolution(in, name);
    if (double(o.width) * o.height > kMaxPicturePixels) bad(name, "picture too large");
    // The scanlines first, in a buffer that grows as they arrive: a resolution line promising more than the
    // file holds costs no more memory than the file.
    int lines = o.scanlines(), length = o.scanlineLength();
    std::vector<unsigned char> raw, line;
    for (int s = 0; s < lines; ++s) {
        readScanline(in, name, line, length);
        raw.insert(raw.end(), line.begin(), line.begin() + size_t(length) * 4);
    }
    p.width = o.width;
    p.height = o.height;
    p.pixels.resize(size_t(p.width) * p.height * 3);
    for (int s = 0; s < lines; ++s)
        for (int k = 0; k < length; ++k) {
            auto [x, y] = o.pixel(s, k);
            decode(&raw[(size_t(s) * length + k) * 4], p.at(x, y));
        }
    return p;
}

HyperspectralPicture readHyperspectralPicture(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) bad(path, "cannot open hyperspectral picture");
    return readHyperspectralPicture(in, path);
}

HyperspectralPicture readHyperspectralPicture(std::istream& in, const std::string& path) {
    HyperspectralPicture h;
    Picture& p = h.picture;
    if (readHeader(in, path, p) != "Radiance_spectra") bad(path, "not a hyperspectral picture (FORMAT=Radiance_spectra)");
    h.bands = std::atoi(headerValue(p.header, "NCOMP=").c_str());
    std::istringstream splits(headerValue(p.header, "WAVELENGTH_SPLITS="));
    double split[4];
    if (!(splits >> split[0] >> split[1] >> split[2] >> split[3])) bad(path, "missing or bad WAVELENGTH_SPLITS=");
    auto nm = [](double v) { return v > 0 && v < 1e5; };
    if (!nm(split[0]) || !nm(split[3]) || split[0] == split[3]) bad(path, "missing or bad WAVELENGTH_SPLITS=");
    h.first = split[0], h.last = split[3];
    if (h.bands <= 3 || h.bands > 1024) bad(path, "bad NCOMP= (4 to 1024 bands)");
    Resolution o = readResolution(in, path);
    if (double(o.width) * o.height * h.bands > kMaxPicturePixels * 3) bad(path, "picture too large");
    p.width = o.width, p.height = o.height;
    size_t stride = size_t(h.bands) + 1;
    std::vector<unsigned char> raw(size_t(o.width) * o.height * stride);  // flat: Radiance does not encode them
    if (!in.read(reinterpret_cast<char*>(raw.data()), std::streamsize(raw.size()))) bad(path, "truncated pixels");
    h.values.resize(size_t(o.width) * o.height * h.bands);
    for (int s = 0; s < o.scanlines(); ++s)
        for (int k = 0; k < o.scanlineLength(); ++k) {
            auto [x, y] = o.pixel(s, k);
            decode(&raw[(size_t(s) * o.scanlineLength() + k) * stride], &h.values[(size_t(y) * o.width + x) * h.bands],
                   h.bands);
        }
    return h;
}

Picture readPicture(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) bad(path, "cannot open picture");
    char magic[4] = {};
    in.read(magic, 4);
    if (in.gcount() == 4 && (unsigned char)magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01)
        return readOpenExrPicture(path);
    in.clear();
    in.seekg(0);
    return readRadiancePicture(in, path);
}

namespace {

// The length of the run of equal bytes at x (stride 4: one component of RGBE pixels), at most 127.
int runAt(const unsigned char* c, int x, int n) {
    int run = 1;
    while (x + run < n && run < 127 && c[4 * (x + run)] == c[4 * x]) ++run;
    return run;
}

// The new run-length encoding of one component, as Radiance 6.1's fwritecolrs lays it out: runs of ≥ 4
// equal bytes, literals of ≤ 128 between them, except that 2 or 3 equal bytes before a run are a run too.
void writeComponent(std::ostream& out, const unsigned char* c, int n) {
    for (int x = 0; x < n;) {
        int start = x, run = 0;
        while (x < n && (run = runAt(c, x, n)) < kMinRunLength) x += run;
        int gap = x - start;
        if (gap >= 2 && gap < kMinRunLength && runAt(c, start, n) == gap) {
            out.put(char(128 + gap));
            out.put(char(c[4 * start]));
        } else {
            for (int k = start; k < x; k += 128) {
                int count = std::min(128, x - k);
                out.put(char(count));
                for (int i = k; i < k + count; ++i) out.put(char(c[4 * i]));
            }
        }
        if (x == n) break;
        out.put(char(128 + run));
        out.put(char(c[4 * x]));
        x += run;
    }
}

}  // namespace

void writeRadiancePicture(std::ostream& out, const Picture& p, bool laterFrame) {
    if (!laterFrame) out << "#?RADIANCE\n";
    for (const std::string& line : p.header)
        // Primaries describe RGB; Radiance writes none for XYZE. FORMAT= is the picture's own.
        if (!isHeaderVariable(line, "FORMAT=") && !(p.xyz && isHeaderVariable(line, "PRIMARIES="))) out << line << '\n';
    out << "FORMAT=" << (p.xyz ? "32-bit_rle_xyze" : "32-bit_rle_rgbe") << "\n\n";
    char resolution[64];  // as Radiance's resolu2str, so that Brume's pictures match Radiance's byte for byte
    std::snprintf(resolution, sizeof resolution, "-Y %8d +X %8d\n", p.height, p.width);
    out << resolution;
    std::vector<unsigned char> line(size_t(p.width) * 4);
    for (int y = 0; y < p.height; ++y) {
        for (int x = 0; x < p.width; ++x) encode(p.at(x, y), &line[size_t(x) * 4]);
        if (p.width < kMinEncodedLength || p.width > kMaxEncodedLength) {
            out.write(reinterpret_cast<const char*>(line.data()), std::streamsize(line.size()));
            continue;
        }
        out.put(2);
        out.put(2);
        out.put(char(p.width >> 8));
        out.put(char(p.width & 0xff));
        for (int component = 0; component < 4; ++component) writeComponent(out, &line[size_t(component)], p.width);
    }
}

}  // namespace brume
