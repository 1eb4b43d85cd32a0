// Brume's rpict against Radiance 6.1's at -ab 0, picture by picture: test/data/rpict/scene.rad seen through
// every view type, a shifted view, a clipped one and a free pixel aspect (views.txt), rendered by Brume's
// rpict with the very command line that made Radiance's reference pictures (make_reference.sh; README.md
// there says why these options and what each picture checks). Every pixel is traced at its centre in both
// (-pj 0 -ps 1), so pixels correspond one to one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "io/picture.h"

namespace {

namespace fs = std::filesystem;

const std::string kData = std::string(BRUME_TEST_DATA) + "/rpict/";

struct ViewCase {
    std::string name, options;  // the picture's name and its view and resolution options
};

// gtest names a case by its picture rather than printing its bytes.
void PrintTo(const ViewCase& v, std::ostream* os) { *os << v.name; }

// views.txt: "name options..." lines; '#' starts a comment line.
std::vector<ViewCase> readViews() {
    std::ifstream in(kData + "views.txt");
    std::vector<ViewCase> views;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream s(line);
        ViewCase v;
        s >> v.name;
        std::getline(s, v.options);
        views.push_back(v);
    }
    return views;
}

std::string commonOptions() {
    std::ifstream in(kData + "options.txt");
    std::string line;
    std::getline(in, line);
    return line;
}

// Brume's picture for `view` in floats (OpenEXR, -ef f): no quantisation on Brume's side. `extra` options
// come last and override.
brume::Picture brumePicture(const ViewCase& view, const std::string& extra = "") {
    fs::path scratch = brume_test::scratchDir("rpict_compat");
    fs::path out = scratch / (view.name + ".exr");
    fs::remove(out);  // rpict never overwrites
    std::string line = "cd '" + kData + "' && RAYPATH=. " + BRUME_BIN_DIR + "/rpict " + commonOptions() + " " +
                       view.options + " " + extra + " -ef f -o '" + out.string() + "' scene.rad";
    brume_test::Output r = brume_test::runCaptured(line, scratch);
    EXPECT_EQ(r.status, 0) << line << "\n" << r.err;
    return r.status == 0 ? brume::readPicture(out.string()) : brume::Picture{};
}

// Reference pixels below this (in every channel) are black: outside a fisheye's image circle, where both
// programs write 0. Everything the scene shows is far brighter (the -av ambient alone gives ≥ 0.01), so the
// floor only separates those pixels, which are checked to be black in Brume too.
constexpr double kBlack = 1e-3;

// A pixel's difference: the RMS over its channels of (Brume − Radiance) relative to Radiance's largest
// channel. RGBE pictures share one exponent per pixel, so every channel is stored to a precision relative to
// the largest: half a unit of an 8-bit mantissa ≥ 128, at most 0.39% (RMS about 0.15%).
double pixelDifference(const float* brume, const float* radiance) {
    double scale = std::max({radiance[0], radiance[1], radiance[2]}), sum = 0;
    for (int c = 0; c < 3; ++c) sum += (brume[c] - radiance[c]) * (brume[c] - radiance[c]);
    return std::sqrt(sum / 3) / scale;
}

// Pixels more than this apart are penumbra pixels (README.md): Radiance at -dj 0 sends one shadow ray to the
// sun's centre and one to the centre of each of the lamp's 64 cells, so where a shadow's edge crosses a
// pixel's centre its value is all or nothing, while Brume's samples over the sun's disc and the lamp give the
// fraction of each source that is visible.
constexpr double kPenumbra = 0.05;

struct Figures {
    double rms = 0, p99 = 0, worst = 0;  // RMS over the pixels within kPenumbra; percentile and worst over all
    int compared = 0, black = 0, penumbra = 0;  // pixels compared, black in the reference, beyond kPenumbra
};

Figures compare(const brume::Picture& brume, const brume::Picture& radiance, bool verbose) {
    std::vector<double> d;
    Figures f;
    for (int y = 0; y < radiance.height; ++y)
        for (int x = 0; x < radiance.width; ++x) {
            const float *b = brume.at(x, y), *r = radiance.at(x, y);
            if (std::max({r[0], r[1], r[2]}) < kBlack) {
                ++f.black;
                EXPECT_LT(std::max({b[0], b[1], b[2]}), kBlack) << "pixel " << x << " " << y << " is black in Radiance";
                continue;
            }
            d.push_back(pixelDifference(b, r));
            if (verbose && d.back() > kPenumbra)
                std::printf("  pixel %2d %2d  Radiance %9.4g %9.4g %9.4g  Brume %9.4g %9.4g %9.4g  %.1f%%\n", x, y,
                            r[0], r[1], r[2], b[0], b[1], b[2], 100 * d.back());
        }
    f.compared = int(d.size());
    if (d.empty()) return f;
    for (double v : d) {
        if (v > kPenumbra) ++f.penumbra;
        else f.rms += v * v;
    }
    f.rms = std::sqrt(f.rms / (d.size() - f.penumbra));
    std::sort(d.begin(), d.end());
    f.p99 = d[size_t(0.99 * (d.size() - 1))];
    f.worst = d.back();
    return f;
}

// The bounds. RMS 1% (the issue's), against RGBE's 0.15% and Brume's noise (two seeds differ by 0.1-0.6% RMS
// over all pixels, nearly all of it in penumbrae). The 99th percentile 3%: the pixels above 1% are shadow
// edges and silhouettes seen through glass, where a pixel's value changes steeply within it. Penumbra
// pixels at most 0.5% of a picture (measured: 0 to 12 of 3008, the most where a shadow edge runs along a
// column of pixel centres).
constexpr double kRms = 0.01, kPercentile99 = 0.03, kPenumbraShare = 0.005;

class RpictCompat : public ::testing::TestWithParam<ViewCase> {};

}  // namespace

TEST_P(RpictCompat, PictureAgreesWithRadiance) {
    const ViewCase& view = GetParam();
    brume::Picture radiance = brume::readPicture(kData + view.name + ".hdr");
    brume::Picture brume = brumePicture(view);
    ASSERT_EQ(brume.width, radiance.width);
    ASSERT_EQ(brume.height, radiance.height);
    EXPECT_NEAR(brume.pixelAspect, radiance.pixelAspect, 1e-6);  // Radiance's header has six decimals
    bool verbose = std::getenv("BRUME_COMPAT_VERBOSE");
    Figures f = compare(brume, radiance, verbose);
    if (verbose)
        std::printf("  %-14s %dx%d: RMS %.3f%%, 99th percentile %.2f%%, worst %.0f%%, %d penumbra, %d black\n",
                    view.name.c_str(), radiance.width, radiance.height, 100 * f.rms, 100 * f.p99, 100 * f.worst,
                    f.penumbra, f.black);
    EXPECT_LT(f.rms, kRms);
    EXPECT_LT(f.p99, kPercentile99);
    EXPECT_LE(f.penumbra, kPenumbraShare * f.compared) << "of " << f.compared << " pixels";
}

INSTANTIATE_TEST_SUITE_P(Views, RpictCompat, ::testing::ValuesIn(readViews()),
                         [](const auto& info) { return info.param.name; });
