#include "io/openexr_file.h"

#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "spectrum/color_output.h"
#include "util/error.h"
#include "util/header.h"
#include "util/pending_file.h"

namespace brume {

namespace {

// Luminance (cd/m²) per unit of a pixel's value: Radiance's WHTEFFICACY (color.h, lumens per watt of its
// equal-energy white) for RGB, whose luminance is 179 × Y; 1 for XYZE, whose Y Radiance 6.1 writes in cd/m²
// (rpict -pXYZ, ra_xyze).
double whiteEfficacy(bool xyz) { return xyz ? 1 : 179; }
const std::vector<std::string> kRgb = {"R", "G", "B"};

Imf::Chromaticities chromaticities(const Primaries& p) {
    auto xy = [](Chromaticity c) { return Imath::V2f(float(c.x), float(c.y)); };
    return Imf::Chromaticities(xy(p.red), xy(p.green), xy(p.blue), xy(p.white));
}
// OpenEXR's convention for CIE XYZ in R, G, B (OpenEXR Technical Introduction, "CIE XYZ Color").
const Imf::Chromaticities kXyzPrimaries({1, 0}, {0, 1}, {0, 0}, {1 / 3.0f, 1 / 3.0f});

// ---- Radiance header lines to attributes ----

std::string trimmed(std::string_view s) {
    size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t\r");
    return b == std::string_view::npos ? std::string() : std::string(s.substr(b, e - b + 1));
}

std::string valueOf(const std::string& line, std::string_view name) {
    return trimmed(std::string_view(line).substr(name.size()));
}

// A header variable is "NAME=value" with no blank in NAME; anything else is a command line.
bool isCommandLine(const std::string& line) {
    size_t equals = line.find('='), blank = line.find_first_of(" \t");
    return equals == std::string::npos || equals == 0 || equals > blank;
}

std::optional<Imf::Chromaticities> primariesOf(const std::string& value) {
    float v[8];
    if (std::sscanf(value.c_str(), "%f %f %f %f %f %f %f %f", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6],
                    &v[7]) != 8)
        return std::nullopt;
    return Imf::Chromaticities({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]});
}

// Seconds since the epoch of a "YYYY:MM:DD hh:mm:ss" date read as UTC (only differences are used).
std::optional<std::time_t> dateSeconds(const std::string& date) {
    std::tm t{};
    if (std::sscanf(date.c_str(), "%d:%d:%d %d:%d:%d", &t.tm_year, &t.tm_mon, &t.tm_mday, &t.tm_hour, &t.tm_min,
                    &t.tm_sec) != 6)
        return std::nullopt;
    t.tm_year -= 1900;
    t.tm_mon -= 1;
    return timegm(&t);
}

std::string joined(const std::vector<std::string>& parts, char separator) {
    std::string s;
    for (const std::string& p : parts) s += (s.empty() ? "" : std::string(1, separator)) + p;
    return s;
}

// The header lines sorted by where they go. Lines an attribute cannot take (a second CAPDATE=, a malformed
// PRIMARIES=) stay in `other`, so nothing is lost.
struct SortedHeader {
    std::vector<std::string> commands, software, views, other;
    std::string capDate, gmt;
    std::optional<Imf::Chromaticities> primaries;
};

bool takeDate(const std::string& line, std::string_view name, std::string& date) {
    if (!isHeaderVariable(line, name) || !date.empty() || !dateSeconds(valueOf(line, name))) return false;
    date = valueOf(line, name);
    return true;
}

SortedHeader sortHeader(const std::vector<std::string>& lines) {
    SortedHeader s;
    for (const std::string& line : lines) {
        if (isHeaderVariable(line, "FORMAT=") || isHeaderVariable(line, "PIXASPECT=") ||
            isHeaderVariable(line, "EXPOSURE="))
            continue;  // the channels and the products below say these
        if (isHeaderVariable(line, "VIEW=")) s.views.push_back(valueOf(line, "VIEW="));
        else if (isHeaderVariable(line, "SOFTWARE=")) s.software.push_back(valueOf(line, "SOFTWARE="));
        else if (takeDate(line, "CAPDATE=", s.capDate) || takeDate(line, "GMT=", s.gmt)) continue;
        else if (isHeaderVariable(line, "PRIMARIES=") && !s.primaries && primariesOf(valueOf(line, "PRIMARIES=")))
            s.primaries = primariesOf(valueOf(line, "PRIMARIES="));
        else if (isCommandLine(line)) s.commands.push_back(line);
        else s.other.push_back(line);
    }
    return s;
}

void addString(Imf::Header& h, const char* name, const std::vector<std::string>& lines, char separator) {
    if (!lines.empty()) h.insert(name, Imf::StringAttribute(joined(lines, separator)));
}

void addDates(Imf::Header& h, const SortedHeader& s) {
    if (!s.capDate.empty()) Imf::addCapDate(h, s.capDate);
    if (!s.capDate.empty() && !s.gmt.empty())
        Imf::addUtcOffset(h, float(std::difftime(*dateSeconds(s.gmt), *dateSeconds(s.capDate))));
}

}  // namespace

Imf::Header exrHeader(const Picture& p) {
    double aspect = headerProduct(p.header, "PIXASPECT="), exposure = headerProduct(p.header, "EXPOSURE=");
    if (!(aspect > 0) || !(exposure > 0)) throw std::runtime_error("bad PIXASPECT= or EXPOSURE= in the header");
    Imf::Header h(p.width, p.height, float(1 / aspect), Imath::V2f(0, 0), 1, Imf::INCREASING_Y, Imf::ZIP_COMPRESSION);
    SortedHeader s = sortHeader(p.header);
    Imf::addChromaticities(h, p.xyz ? kXyzPrimaries : s.primaries.value_or(chromaticities(kRadiancePrimaries)));
    Imf::addWhiteLuminance(h, float(whiteEfficacy(p.xyz) / exposure));
    addDates(h, s);
    addString(h, "comments", s.commands, '\n');
    addString(h, "Software", s.software, '\n');
    addString(h, "view", s.views, ' ');
    addString(h, "radianceHeader", s.other, '\n');
    return h;
}

namespace {

// ---- pixels: channels interleaved in memory, as Picture::pixels has R, G, B ----

// Slices for `names.size()` channels of `size`-byte values interleaved pixel by pixel, rows of the data
// window `dw` from the top.
void addSlices(Imf::FrameBuffer& frame, const std::vector<std::string>& names, const void* first, size_t size,
               Imf::PixelType type, const Imath::Box2i& dw) {
    size_t xStride = names.size() * size, yStride = xStride * size_t(dw.max.x - dw.min.x + 1);
    for (size_t c = 0; c < names.size(); ++c)
        frame.insert(names[c], Imf::Slice::Make(type, static_cast<const char*>(first) + c * size, dw, xStride, yStride));
}

// Half would turn values beyond its range into infinities (a sun's disc is ~10^7), which spread to every
// pixel a filter touches; the largest half keeps them finite and as bright as half can say.
std::vector<half> halves(const float* values, size_t n) {
    std::vector<half> h(n);
    for (size_t i = 0; i < n; ++i) h[i] = half(std::clamp(values[i], -kLargestHalf, kLargestHalf));
    return h;
}

}  // namespace

void writeExrPicture(const std::string& path, Imf::Header header, const Picture& p, ExrPixels pixels,
                     const std::vector<std::string>& moreNames, const float* more) {
    // OpenEXR converts pixel types when reading but not when writing: the frame buffer has the file's type.
    Imf::PixelType type = pixels == ExrPixels::half ? Imf::HALF : Imf::FLOAT;
    size_t size = pixels == ExrPixels::half ? sizeof(half) : sizeof(float), count = size_t(p.width) * p.height;
    std::vector<half> halfValues[2];  // the copies half pixels are written from
    Imf::FrameBuffer frame;
    auto add = [&](const std::vector<std::string>& names, const float* values, std::vector<half>& copy) {
        for (const std::string& name : names) header.channels().insert(name, Imf::Channel(type));
        if (pixels == ExrPixels::half) copy = halves(values, count * names.size());
        addSlices(frame, names, pixels == ExrPixels::half ? static_cast<const void*>(copy.data()) : values, size, type,
                  header.dataWindow());
    };
    add(kRgb, p.pixels.data(), halfValues[0]);
    add(moreNames, more, halfValues[1]);
    PendingFile file(path);
    {
        Imf::OutputFile out(file.name().c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(p.height);
    }
    file.commit();
}

void writeOpenExrPicture(const std::string& path, const Picture& p, ExrPixels pixels) {
    try {
        writeExrPicture(path, exrHeader(p), p, pixels);
    } catch (const std::exception& e) {
        throw Error("cannot write " + path + ": " + e.what());
    }
}

namespace {

// ---- attributes back to Radiance header lines ----

const std::string* stringAttribute(const Imf::Header& h, const char* name) {
    const auto* a = h.findTypedAttribute<Imf::StringAttribute>(name);
    return a ? &a->value() : nullptr;
}

void addLines(std::vector<std::string>& lines, const std::string* text, const std::string& prefix) {
    if (!text) return;
    std::istringstream in(*text);
    for (std::string line; std::getline(in, line);) lines.push_back(prefix + line);
}

bool isXyz(const Imf::Chromaticities& c) {
    auto near = [](Imath::V2f a, Imath::V2f b) { return (a - b).length() < 1e-4f; };
    return near(c.red, kXyzPrimaries.red) && near(c.green, kXyzPrimaries.green) && near(c.blue, kXyzPrimaries.blue);
}

std::string formatted(const char* format, double v) {
    char s[64];
    std::snprintf(s, sizeof s, format, v);
    return s;
}

void addDateLines(std::vector<std::string>& lines, const Imf::Header& h) {
    if (!Imf::hasCapDate(h)) return;
    const std::string& capDate = Imf::capDate(h);
    lines.push_back("CAPDATE= " + capDate);
    std::optional<std::time_t> local = dateSeconds(capDate);
    if (!Imf::hasUtcOffset(h) || !local) return;
    std::time_t gmt = *local + std::time_t(std::lround(Imf::utcOffset(h)));
    std::tm t{};
    char text[32];
    std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", gmtime_r(&gmt, &t));
    lines.push_back(std::string("GMT= ") + text);
}

std::string primariesLine(const Imf::Chromaticities& c) {
    return brume::primariesLine(Primaries{{c.red.x, c.red.y}, {c.green.x, c.green.y}, {c.blue.x, c.blue.y},
                                          {c.white.x, c.white.y}});
}

// Fills the header lines, exposure and pixel aspect from the attributes, in rpict's order.
void readHeaderLines(const Imf::Header& h, Picture& p) {
    std::vector<std::string>& lines = p.header;
    addLines(lines, stringAttribute(h, "comments"), "");
    addLines(lines, stringAttribute(h, "Software"), "SOFTWARE= ");
    addLines(lines, stringAttribute(h, "radianceHeader"), "");
    if (const std::string* view = stringAttribute(h, "view")) lines.push_back("VIEW= " + *view);
    p.pixelAspect = 1 / double(h.pixelAspectRatio());
    if (std::abs(p.pixelAspect - 1) > 1e-6) lines.push_back(formatted("PIXASPECT=%f", p.pixelAspect));
    addDateLines(lines, h);
    p.xyz = Imf::hasChromaticities(h) && isXyz(Imf::chromaticities(h));
    if (Imf::hasWhiteLuminance(h)) p.exposure = whiteEfficacy(p.xyz) / Imf::whiteLuminance(h);
    if (std::abs(p.exposure - 1) > 1e-6) lines.push_back(formatted("EXPOSURE=%.4e", p.exposure));
    if (Imf::hasChromaticities(h) && !p.xyz) lines.push_back(primariesLine(Imf::chromaticities(h)));
}

// Pictures without R, G, B (luminance alone, or luminance and chroma): the RGBA interface converts them.
void readLuminanceChroma(const std::string& path, Picture& p) {
    Imf::RgbaInputFile file(path.c_str());
    Imath::Box2i dw = file.dataWindow();
    Imf::Array2D<Imf::Rgba> rgba(p.height, p.width);
    file.setFrameBuffer(&rgba[0][0] - dw.min.x - dw.min.y * p.width, 1, p.width);
    file.readPixels(dw.min.y, dw.max.y);
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            float* o = p.at(x, y);
            o[0] = rgba[y][x].r;
            o[1] = rgba[y][x].g;
            o[2] = rgba[y][x].b;
        }
}

}  // namespace

Picture exrPicture(const Imf::Header& h) {
    Picture p;
    p.width = h.dataWindow().max.x - h.dataWindow().min.x + 1;
    p.height = h.dataWindow().max.y - h.dataWindow().min.y + 1;
    if (double(p.width) * p.height > kMaxPicturePixels) throw std::runtime_error("picture too large");
    p.pixels.resize(size_t(p.width) * p.height * 3);
    readHeaderLines(h, p);
    return p;
}

void readExrPixels(Imf::InputFile& file, const std::string& path, Picture& p, const std::vector<std::string>& moreNames,
                   float* more) {
    const Imath::Box2i& dw = file.header().dataWindow();
    const Imf::ChannelList& channels = file.header().channels();
    bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    Imf::FrameBuffer frame;
    if (rgb) addSlices(frame, kRgb, p.pixels.data(), sizeof(float), Imf::FLOAT, dw);
    addSlices(frame, moreNames, more, sizeof(float), Imf::FLOAT, dw);
    if (frame.begin() != frame.end()) {
        file.setFrameBuffer(frame);
        file.readPixels(dw.min.y, dw.max.y);
    }
    if (!rgb) readLuminanceChroma(path, p);
}

Picture readOpenExrPicture(const std::string& path) {
    try {
        Imf::InputFile file(path.c_str());
        Picture p = exrPicture(file.header());
        readExrPixels(file, path, p);
        return p;
    } catch (const std::exception& e) {
        throw Error(path + ": " + e.what());
    }
}

}  // namespace brume
