#include "render/frame_output.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ostream>

#include "io/openexr_picture.h"
#include "io/spectral_picture.h"
#include "spectrum/colorimetry.h"
#include "util/error.h"
#include "util/pending_file.h"

namespace brume {

namespace {

// The conversion's span [begin, end) in the pattern, or begin = npos when there is none.
std::pair<size_t, size_t> conversion(const std::string& pattern) {
    std::pair<size_t, size_t> found{std::string::npos, 0};
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            ++i;
            continue;
        }
        size_t j = i + 1;
        while (j < pattern.size() && std::strchr("-+ #0", pattern[j])) ++j;
        while (j < pattern.size() && std::isdigit((unsigned char)pattern[j])) ++j;
        if (j >= pattern.size() || (pattern[j] != 'd' && pattern[j] != 'i'))
            throw Error("output file pattern '" + pattern + "': only one %d conversion (for the frame number) is allowed");
        if (found.first != std::string::npos)
            throw Error("output file pattern '" + pattern + "' has more than one frame number");
        found = {i, j + 1};
        i = j;
    }
    return found;
}

std::string unescaped(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        out += s[i];
        if (s[i] == '%' && i + 1 < s.size() && s[i + 1] == '%') ++i;
    }
    return out;
}

bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

bool namesFrames(const std::string& pattern) { return conversion(pattern).first != std::string::npos; }

std::string frameFileName(const std::string& pattern, int number) {
    auto [begin, end] = conversion(pattern);
    if (begin == std::string::npos) return unescaped(pattern);
    char buf[64];
    std::snprintf(buf, sizeof buf, pattern.substr(begin, end - begin).c_str(), number);
    return unescaped(pattern.substr(0, begin)) + buf + unescaped(pattern.substr(end));
}

bool claimFile(const std::string& path) {
    int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0666);
    if (fd < 0) {
        if (errno == EEXIST) return false;
        throw Error("cannot open output file \"" + path + "\": " + std::strerror(errno));
    }
    ::close(fd);
    return true;
}

void writePictureFile(const std::string& path, const Picture& picture, bool exrFloat, const PixelSpectra* spectra) {
    if (endsWith(path, ".exr")) {
        if (!exrFloat && std::any_of(picture.pixels.begin(), picture.pixels.end(), [](float v) { return v > kLargestHalf; }))
            warn(path + ": values above " + std::to_string(int(kLargestHalf)) + " (a light source, the sun) clamped in half floats; -ef f keeps them");
        ExrPixels pixels = exrFloat ? ExrPixels::float32 : ExrPixels::half;
        if (!spectra) return writeOpenExrPicture(path, picture, pixels);
        // The layout's bands hold spectral radiance, W·m⁻²·sr⁻¹·nm⁻¹: some 400 times below Radiance's values,
        // too small for half floats to keep dim pixels to 3 digits, hence floats.
        pixels = ExrPixels::float32;
        SpectralPixels bands;
        const SpectralSampling& s = spectralSampling();
        for (int i = 0; i < s.channels; ++i) bands.wavelengths.push_back(s.bandCentre(i));
        float scale = float(spectralRadiancePerValue());
        bands.values.reserve(spectra->values.size());
        for (float v : spectra->values) bands.values.push_back(v * scale);
        return writeSpectralOpenExrPicture(path, picture, bands, pixels);
    }
    writeWhole(path, [&picture](std::ostream& out) { writeRadiancePicture(out, picture); });
}

void writeDepthFile(const std::string& path, const std::vector<float>& depth) {
    writeWhole(path, [&depth](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(depth.data()), std::streamsize(depth.size() * sizeof(float)));
    });
}

}  // namespace brume
