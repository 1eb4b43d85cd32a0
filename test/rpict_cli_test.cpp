// rpict as a program: its picture stream and header, sequences and file outputs, its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <fstream>
#include <sstream>
#include <string>

#include "cli.h"
#include "io/picture.h"
#include "io/spectral_picture.h"
#include "medium/testing.h"

namespace {

namespace fs = std::filesystem;

using brume_test::Output;

fs::path dir() { return brume_test::scratchDir("rpict"); }

Output rpict(const std::string& args, const std::string& input = "") {
    std::ofstream(dir() / "in") << input;
    return brume_test::runCaptured("cd " + dir().string() + " && " + BRUME_BIN_DIR + std::string("/rpict ") + args + " < in",
                                   dir());
}

brume::Picture picture(const std::string& bytes) {
    std::istringstream in(bytes);
    return brume::readRadiancePicture(in, "rpict output");
}

const char* kScene =
    "void light lum 0 0 3 100 100 100\n"
    "lum sphere bulb 0 0 4 0 3 2 0.2\n"
    "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
    "grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n";

class RpictCli : public ::testing::Test {
protected:
    void SetUp() override {
        fs::remove_all(dir());
        std::ofstream(dir() / "s.rad") << kScene;
    }
};

const char* kView = "-vp 0 -2 1 -vd 0 1 -0.2 -vh 50 -vv 40";

}  // namespace

// Radiance's picture header: the command, SOFTWARE=, VIEW= (the full view, readable back), PIXASPECT= only
// when not 1, FORMAT=, and the resolution line; -pa 1 fits the resolution to the view's aspect.
TEST_F(RpictCli, HeaderFollowsRadianceLayout) {
    Output r = rpict(std::string("-x 40 -y 40 ") + kView + " s.rad");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.rfind("#?RADIANCE\nrpict -x 40 -y 40 -vp 0 -2 1", 0), 0u) << r.out.substr(0, 200);
    EXPECT_NE(r.out.find("\nSOFTWARE= Brume "), std::string::npos);
    EXPECT_NE(r.out.find("\nVIEW= -vtv -vp 0 -2 1 -vd 0 1 -0.2 -vu 0 0 1 -vh 50 -vv 40 -vo 0 -va 0 -vs 0 -vl 0\n"),
              std::string::npos);
    EXPECT_EQ(r.out.find("PIXASPECT"), std::string::npos);
    EXPECT_NE(r.out.find("\nFORMAT=32-bit_rle_rgbe\n\n-Y "), std::string::npos);
    brume::Picture p = picture(r.out);
    EXPECT_EQ(p.width, 40);
    EXPECT_EQ(p.height, int(40 * std::tan(20 * M_PI / 180) / std::tan(25 * M_PI / 180) + .5));
}

// -pa 0 keeps an odd resolution and states the pixel aspect, as Radiance.
TEST_F(RpictCli, OddResolutionWithFreePixelAspect) {
    Output r = rpict(std::string("-x 9 -y 8 -pa 0 -vh 45 -vv 45 s.rad"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("\nPIXASPECT=1.125000\n"), std::string::npos);
    brume::Picture p = picture(r.out);
    EXPECT_EQ(p.width, 9);
    EXPECT_EQ(p.height, 8);
}

// -S: one picture per view line on stdin, views cumulative, numbered into -o names; an existing frame is
// skipped (another process renders it) and left as it was.
TEST_F(RpictCli, SequencesWriteNumberedFramesAndSkipExistingOnes) {
    std::ofstream(dir() / "f2.hdr") << "taken";
    Output r = rpict(std::string("-x 8 -y 8 -S 1 -o f%d.hdr s.rad"),
                     "VIEW= -vp 0 -2 1 -vd 0 1 0\nnot a view\nrpict -vh 30\nVIEW= -vp 0 -3 1 -T 2.5\n");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(r.out.empty());
    brume::Picture f1 = brume::readPicture((dir() / "f1.hdr").string()), f3 = brume::readPicture((dir() / "f3.hdr").string());
    EXPECT_EQ(brume_test::slurp(dir() / "f2.hdr"), "taken");
    auto has = [](const brume::Picture& p, const std::string& text) {
        for (const std::string& line : p.header)
            if (line.find(text) != std::string::npos) return true;
        return false;
    };
    EXPECT_TRUE(has(f1, "VIEW= -vtv -vp 0 -2 1 -vd 0 1 0 -vu 0 0 1 -vh 45 "));
    EXPECT_TRUE(has(f3, "VIEW= -vtv -vp 0 -3 1 -vd 0 1 0 -vu 0 0 1 -vh 30 "));  // -vd and -vh carried on
    EXPECT_TRUE(has(f3, "FRAME=3"));
    EXPECT_TRUE(has(f3, "SCENETIME= 2.5"));
    EXPECT_FALSE(fs::exists(dir() / "f4.hdr"));
}

// Without -o, the frames of a sequence follow one another on the standard output as Radiance's do: one
// "#?RADIANCE" header, each later frame's header starting at its FRAME= line (as Radiance's ra_rgbe reads).
TEST_F(RpictCli, SequenceFramesFollowOneAnotherOnTheOutput) {
    Output r = rpict("-x 8 -y 8 -S 1 s.rad", "VIEW= -vp 0 -2 1\nVIEW= -vp 0 -3 1\n");
    ASSERT_EQ(r.status, 0) << r.err;
    size_t second = r.out.find("FRAME=2\nVIEW= -vtv -vp 0 -3 1 ");
    ASSERT_NE(second, std::string::npos);
    EXPECT_EQ(r.out.find("#?RADIANCE", 1), std::string::npos);
    EXPECT_NE(r.out.find("\nSOFTWARE= Brume 0.1\nFRAME=1\nVIEW= -vtv -vp 0 -2 1 "), std::string::npos) << r.out;
    EXPECT_EQ(picture(r.out.substr(0, second)).width, 8);
    EXPECT_EQ(picture("#?RADIANCE\n" + r.out.substr(second)).width, 8);
}

// A camera path at 4 frames a second over 1 s: 5 frames, each with its scene time.
TEST_F(RpictCli, CameraPathGivesTimedFrames) {
    std::ofstream(dir() / "path.txt") << "0 0 -3 1 0 1 0\n1 0 -2 1 0 1 0\n";
    Output r = rpict("-x 8 -y 8 -path path.txt -fps 4 -o walk%02d.hdr s.rad");
    ASSERT_EQ(r.status, 0) << r.err;
    for (int i = 1; i <= 5; ++i) EXPECT_TRUE(fs::exists(dir() / ("walk0" + std::to_string(i) + ".hdr"))) << i;
    EXPECT_FALSE(fs::exists(dir() / "walk06.hdr"));
    std::string third = brume_test::slurp(dir() / "walk03.hdr");
    EXPECT_NE(third.find("SCENETIME= 0.5\n"), std::string::npos);
    EXPECT_NE(third.find("VIEW= -vtv -vp 0 -2.5 1 "), std::string::npos);
}

// -z writes one float per pixel: the distance to what the pixel sees.
TEST_F(RpictCli, DepthFileHoldsAFloatPerPixel) {
    Output r = rpict("-x 8 -y 8 -vp 0 0 1 -vd 0 0 -1 -vu 0 1 0 -vh 10 -vv 10 -z d.z -o p.hdr s.rad");
    ASSERT_EQ(r.status, 0) << r.err;
    std::string z = brume_test::slurp(dir() / "d.z");
    ASSERT_EQ(z.size(), 64 * sizeof(float));
    float centre;
    std::memcpy(&centre, z.data() + (4 * 8 + 4) * sizeof(float), sizeof centre);
    EXPECT_NEAR(centre, 1.0, 0.01);
}

TEST_F(RpictCli, ErrorsAreClearAndLeaveNoPicture) {
    Output r = rpict("-vh 200 s.rad");
    EXPECT_NE(r.status, 0);
    EXPECT_EQ(r.err, "rpict: illegal horizontal view size\n");
    EXPECT_TRUE(r.out.empty());
    std::ofstream(dir() / "old.hdr") << "keep";
    r = rpict("-x 8 -y 8 -o old.hdr s.rad");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("rpict: cannot open output file \"old.hdr\""), std::string::npos) << r.err;
    EXPECT_EQ(brume_test::slurp(dir() / "old.hdr"), "keep");
    r = rpict("-x 8 -y 8 -o new.hdr missing.rad");
    EXPECT_NE(r.status, 0);
    EXPECT_FALSE(fs::exists(dir() / "new.hdr"));
    r = rpict("-x 8 -y 8 -o f%d.hdr s.rad");
    EXPECT_NE(r.err.find("no sequence"), std::string::npos) << r.err;
    r = rpict("-pm 1 s.rad");
    EXPECT_NE(r.err.find("motion blur"), std::string::npos) << r.err;
    r = rpict("s.rad -x 8");
    EXPECT_NE(r.status, 0);
    r = rpict("-S 1 -path p.txt s.rad");
    EXPECT_NE(r.err.find("-S and -path are exclusive"), std::string::npos) << r.err;
    r = rpict("-S 1 -", "VIEW= -vp 0 0 0\n");
    EXPECT_NE(r.err.find("cannot be read from the standard input with -S"), std::string::npos) << r.err;
    r = rpict("-S -2 s.rad");
    EXPECT_NE(r.err.find("bad sequence start -2"), std::string::npos) << r.err;
    r = rpict("-ef x -o p.exr s.rad");
    EXPECT_NE(r.err.find("bad OpenEXR pixel type 'x'"), std::string::npos) << r.err;
    r = rpict("-path missing.txt s.rad");
    EXPECT_NE(r.err.find("missing.txt: cannot open camera path"), std::string::npos) << r.err;
    r = rpict("-x 100000 -y 100000 s.rad");
    EXPECT_NE(r.err.find("rpict: bad resolution 100000x100000"), std::string::npos) << r.err;
}

// Radiance's rpict defaults (-defaults), where they differ from rtrace's.
TEST_F(RpictCli, DefaultsAreRadiancesRpictDefaults) {
    Output r = rpict("-defaults");
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* line : {"-x 512", "-y 512", "-pj 0.670000", "-ps 4", "-pt 0.050000", "-dt 0.050000",
                             "-dc 0.500000", "-ds 0.250000", "-dr 1", "-st 0.150000", "-aa 0.200000", "-ar 64",
                             "-ad 512", "-as 128", "-lr 7", "-u-", "-vtv"})
        EXPECT_NE(r.out.find(std::string("\n") + line), std::string::npos) << line;
}

// The promise of the man page, end to end: with -pj 0 -ps 1 each pixel of a float OpenEXR picture is, bit for
// bit, rtrace's value for the ray vwrays gives that pixel (same options, -u-); the view is in the file.
TEST_F(RpictCli, PixelsEqualVwraysThroughRtrace) {
    std::string bin = BRUME_BIN_DIR, view = std::string(" -x 11 -y 7 -pa 0 ") + kView;
    Output r = rpict("-pj 0 -ps 1 -ab 1 -ad 16 -ef f -o p.exr" + view + " s.rad");
    ASSERT_EQ(r.status, 0) << r.err;
    Output rays = brume_test::runCaptured("cd " + dir().string() + " && " + bin + "/vwrays -fd" + view + " | " + bin +
                                              "/rtrace -h -fdf -ab 1 -ad 16 -aa .2 -ar 64 -as 128 -lr 7 -dt .05 -dc .5 "
                                              "-ds .25 -dr 1 -st .15 -u- s.rad",
                                          dir());
    ASSERT_EQ(rays.status, 0) << rays.err;
    brume::Picture p = brume::readPicture((dir() / "p.exr").string());
    ASSERT_EQ(rays.out.size(), 11 * 7 * 3 * sizeof(float));
    std::vector<float> values(11 * 7 * 3);
    std::memcpy(values.data(), rays.out.data(), rays.out.size());
    ASSERT_EQ(p.pixels.size(), values.size());
    for (size_t i = 0; i < values.size(); ++i) ASSERT_EQ(p.pixels[i], values[i]) << std::setprecision(9) << "pixel " << i / 3 << " of 77: " << p.pixels[i] << " vs " << values[i];
    bool hasView = false;
    for (const std::string& line : p.header) hasView |= line.rfind("VIEW= -vtv -vp 0 -2 1 ", 0) == 0;
    EXPECT_TRUE(hasView);
}

// In bands, an .exr output is a spectral OpenEXR (spectral_picture.h): its bands are the pixels' spectra in
// W·m⁻²·sr⁻¹·nm⁻¹ (Radiance's value × 179 / (683 ∫ȳ)), its R, G, B what rtrace -pRGB gives for the same rays.
TEST_F(RpictCli, SpectralPicturesHoldEveryBand) {
    std::string bin = BRUME_BIN_DIR, view = std::string(" -x 6 -y 5 -pa 0 ") + kView;
    Output r = rpict("-cs 41 -pj 0 -ps 1 -ab 0 -o p.exr" + view + " s.rad");
    ASSERT_EQ(r.status, 0) << r.err;
    auto [p, spectrum] = brume::readSpectralOpenExrPicture((dir() / "p.exr").string());
    ASSERT_EQ(spectrum.wavelengths.size(), 41u);
    EXPECT_NEAR(spectrum.wavelengths[0], 775.1219512, 1e-6);
    auto vwrays = [&](const std::string& output) {
        Output o = brume_test::runCaptured("cd " + dir().string() + " && " + bin + "/vwrays -fd" + view + " | " + bin +
                                               "/rtrace -h -fdf -cs 41 -ab 0 -dt .05 -dc .5 -ds .25 -dr 1 -lr 7 -st .15 -u- " +
                                               output + " s.rad",
                                           dir());
        std::vector<float> v(o.out.size() / sizeof(float));
        std::memcpy(v.data(), o.out.data(), o.out.size());
        return v;
    };
    std::vector<float> rgb = vwrays("-pRGB"), bands = vwrays("-co");
    ASSERT_EQ(rgb.size(), p.pixels.size());
    for (size_t i = 0; i < rgb.size(); ++i) EXPECT_NEAR(p.pixels[i], rgb[i], 1e-5 * (1 + rgb[i])) << "value " << i;
    ASSERT_EQ(bands.size(), spectrum.values.size());
    double perValue = 179 / (683.002 * 106.856895);  // ∫ȳ dλ of the CIE 1931 table at 1 nm
    for (size_t i = 0; i < bands.size(); ++i)
        EXPECT_NEAR(spectrum.values[i], bands[i] * perValue, 1e-4 * bands[i] * perValue + 1e-9) << "value " << i;
    Output hdr = rpict("-cs 41 -pXYZ -ps 1" + view + " s.rad");
    EXPECT_EQ(picture(hdr.out).xyz, true);
}

// Smoke that changes in time (key frames at 0 and 10 s), a sequence of frames at 0, 10 and 0 s through the
// irradiance cache: with -af, one file keeps the records of both windows of time (from 0 s, and 10 s, the
// last instant with data, alone), and the pictures are those rendered without a file, bit for bit (a file
// changes no value).
TEST_F(RpictCli, OneCacheFileServesFramesAtSeveralInstants) {
    using namespace brume::medium::testing;
    writeGrid(dir() / "thin.vdb", boxGrid({-20, -20, 0}, {20, 20, 20}, 0.1f, 0.1));
    writeGrid(dir() / "thick.vdb", boxGrid({-20, -20, 0}, {20, 20, 20}, 2.0f, 0.1));
    std::ofstream(dir() / "smoke.rad") << kScene << "void smoke s 4 0 thin.vdb 10 thick.vdb 0 7 1 1 1 .8 .8 .8 .3\n";
    const std::string views = "VIEW= -vp 0 -2 1 -vd 0 1 -0.2 -T 0\nVIEW= -vp 0 -2 1 -T 10\nVIEW= -vp 0 -2 1 -T 0\n";
    const std::string options = "-u- -x 12 -y 12 -ab 1 -ad 32 -aa .2 -S 1 smoke.rad";
    Output plain = rpict("-o plain%d.hdr " + options, views);
    ASSERT_EQ(plain.status, 0) << plain.err;
    Output cached = rpict("-af smoke.cache -o cached%d.hdr " + options, views);
    ASSERT_EQ(cached.status, 0) << cached.err;
    for (int i = 1; i <= 3; ++i) {
        brume::Picture a = picture(brume_test::slurp(dir() / ("plain" + std::to_string(i) + ".hdr")));
        brume::Picture b = picture(brume_test::slurp(dir() / ("cached" + std::to_string(i) + ".hdr")));
        EXPECT_EQ(a.pixels, b.pixels) << "frame " << i;
    }
    // The instants differ in light: thick smoke at 10 s darkens the floor.
    brume::Picture early = picture(brume_test::slurp(dir() / "plain1.hdr"));
    brume::Picture late = picture(brume_test::slurp(dir() / "plain2.hdr"));
    EXPECT_LT(late.pixels[late.pixels.size() / 2], 0.9f * early.pixels[early.pixels.size() / 2]);
    // A second run reads the records of both instants and makes few new ones.
    Output again = rpict("-t 1 -af smoke.cache -o again%d.hdr " + options, views);
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_NE(again.err.find("rpict: irradiance cache: "), std::string::npos) << again.err;
}
