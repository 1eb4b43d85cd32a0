#include "io/spectral_picture.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <regex>
#include <set>
#include <stdexcept>

#include "io/openexr_file.h"
#include "util/error.h"

namespace brume {

namespace {

constexpr double kSpeedOfLight = 299792458;  // m/s

// The band's channel: its centre in nanometres with six decimals, a comma for the point.
std::string channelName(double nm) {
    char digits[64];
    char* end = std::to_chars(digits, digits + sizeof digits, nm, std::chars_format::fixed, 6).ptr;
    std::replace(digits, end, '.', ',');
    return "S0." + std::string(digits, end) + "nm";
}

// Powers of ten of the SI prefixes the layout allows.
int prefixExponent(const std::string& prefix) {
    static const std::pair<const char*, int> kPrefixes[] = {
        {"Y", 24}, {"Z", 21}, {"E", 18}, {"P", 15}, {"T", 12}, {"G", 9}, {"M", 6}, {"k", 3}, {"h", 2},
        {"da", 1}, {"", 0},   {"d", -1}, {"c", -2}, {"m", -3}, {"u", -6}, {"n", -9}, {"p", -12}};
    return std::find_if(std::begin(kPrefixes), std::end(kPrefixes), [&](auto& p) { return prefix == p.first; })->second;
}

// The centre in nm of an S0 channel, in any spelling the layout allows; nothing for other channels.
std::optional<double> bandCentre(const std::string& channel) {
    static const std::regex kS0(R"(S0\.(\d*,?\d*(?:[Ee][+-]?\d+)?)(Y|Z|E|P|T|G|M|k|h|da|d|c|m|u|n|p)?(m|Hz))");
    std::smatch m;
    if (!std::regex_match(channel, m, kS0)) return std::nullopt;
    std::string number = m[1];
    std::replace(number.begin(), number.end(), ',', '.');
    double value = 0;
    auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (error != std::errc() || end != number.data() + number.size()) return std::nullopt;
    // Powers of ten rather than a product of factors, so that "550nm" is exactly 550.
    int exponent = prefixExponent(m[2]);
    double nm = m[3] == "m" ? value * std::pow(10.0, exponent + 9) : kSpeedOfLight * std::pow(10.0, 9 - exponent) / value;
    return std::isfinite(nm) && nm > 0 ? std::optional(nm) : std::nullopt;
}

}  // namespace

void writeSpectralOpenExrPicture(const std::string& path, const Picture& p, const SpectralPixels& s,
                                 ExrPixels pixels) {
    try {
        size_t bands = s.wavelengths.size();
        if (bands == 0 || s.values.size() != p.pixels.size() / 3 * bands)
            throw std::runtime_error("the spectrum does not fit the picture");
        std::vector<std::string> names;
        std::set<std::string> taken;
        for (double nm : s.wavelengths) {
            if (!(std::isfinite(nm) && nm > 0)) throw std::runtime_error("band centre " + std::to_string(nm) + " nm");
            names.push_back(channelName(nm));
            if (!taken.insert(names.back()).second) throw std::runtime_error("two bands named " + names.back());
        }
        Imf::Header header = exrHeader(p);
        header.insert("spectralLayoutVersion", Imf::StringAttribute("1.0"));
        header.insert("emissiveUnits", Imf::StringAttribute("W.m^-2.sr^-1"));
        writeExrPicture(path, header, p, pixels, names, s.values.data());
    } catch (const std::exception& e) {
        throw Error("cannot write " + path + ": " + e.what());
    }
}

std::pair<Picture, SpectralPixels> readSpectralOpenExrPicture(const std::string& path) {
    try {
        Imf::InputFile file(path.c_str());
        std::vector<std::pair<double, std::string>> bands;
        const Imf::ChannelList& channels = file.header().channels();
        for (auto c = channels.begin(); c != channels.end(); ++c)
            if (std::optional<double> nm = bandCentre(c.name())) bands.emplace_back(*nm, c.name());
        if (bands.empty()) throw std::runtime_error("no spectral channels (S0.…nm)");
        std::sort(bands.begin(), bands.end(), std::greater<>());
        Picture p = exrPicture(file.header());
        if (double(p.width) * p.height * double(bands.size()) > 3 * kMaxPicturePixels)
            throw std::runtime_error("picture too large");
        SpectralPixels s;
        std::vector<std::string> names;
        for (auto& [nm, name] : bands) {
            s.wavelengths.push_back(nm);
            names.push_back(name);
        }
        s.values.resize(size_t(p.width) * p.height * bands.size());
        readExrPixels(file, path, p, names, s.values.data());
        return {std::move(p), std::move(s)};
    } catch (const std::exception& e) {
        throw Error(path + ": " + e.what());
    }
}

}  // namespace brume
