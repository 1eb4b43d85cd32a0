// rcontrib and rfluxmtx as programs: Radiance's headers and layouts (stdout, -o files per modifier and per bin,
// ASCII and binary), -c, -V, rfluxmtx's receivers as Radiance's asks rcontrib for them, their refusals; and end
// to end against Radiance, a year of daylight in a side-lit office through rfluxmtx and rmtxop as Honeybee
// runs them, against Radiance's converged 2-phase reference (test/data/rcontrib/office_reference.txt).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "io/picture.h"

namespace {

namespace fs = std::filesystem;

using brume_test::Output;
using brume_test::slurp;

const fs::path kData = fs::path(BRUME_TEST_DATA) / "rcontrib";
const fs::path kWeather = fs::path(BRUME_SHARED_DATA) / "weather";
constexpr double kPi = std::numbers::pi;

// An open sky above and a ground below, each a glow of radiance 1 (or `sky` for the sky).
std::string openSky(double sky = 1) {
    std::ostringstream s;
    s << "void glow sky_glow 0 0 4 " << sky << " " << sky << " " << sky << " 0\nsky_glow source sky 0 0 4 0 0 1 180\n"
      << "void glow ground_glow 0 0 4 1 1 1 0\nground_glow source ground 0 0 4 0 0 -1 180\n"
      << "void plastic grey 0 0 5 .5 .5 .5 0 0\n";
    return s.str();
}

struct Case {
    fs::path dir;
    Case(const std::string& name, const std::string& scene, const std::string& rays)
        : dir(brume_test::scratchDir("rcontrib_" + name)) {
        std::ofstream(dir / "scene.rad") << scene;
        std::ofstream(dir / "rays.txt") << rays;
    }
    Output run(const std::string& args) const {
        return brume_test::runBrume("set -f; rcontrib " + args + " scene.rad < rays.txt", dir);
    }
};

// A header's variable `name` ("NCOLS="), or "".
std::string headerValue(const std::string& text, const std::string& name) {
    std::istringstream in(text.substr(0, text.find("\n\n")));
    for (std::string line; std::getline(in, line);)
        if (line.rfind(name, 0) == 0) return line.substr(name.size(), line.find_last_not_of(' ') + 1 - name.size());
    return "";
}

// The ASCII rows after the header, as numbers.
std::vector<std::vector<double>> rows(const std::string& text) {
    std::vector<std::vector<double>> out;
    std::istringstream in(text.substr(text.find("\n\n") + 2));
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        out.emplace_back();
        for (double v; words >> v;) out.back().push_back(v);
    }
    return out;
}

double sumOfFirstComponents(const std::vector<double>& row, size_t from, size_t to) {
    double s = 0;
    for (size_t i = from; i < to; ++i) s += row[3 * i];
    return s;
}

const char* kReinhart = "-e MF:1 -f reinhart.cal -b rbin -bn Nrbins";

TEST(RcontribCli, WritesRadiancesHeaderAndRows) {
    Case c("header", openSky(), "0 0 0 0 0 1\n0 0 0 1 0 0\n");
    Output o = c.run(std::string("-I -ab 1 -ad 256 -y 2 ") + kReinhart + " -m sky_glow -m ground_glow");
    ASSERT_EQ(o.status, 0) << o.err;
    EXPECT_EQ(o.err, "");
    EXPECT_EQ(o.out.rfind("#?RADIANCE\n", 0), 0u);
    EXPECT_NE(o.out.find("\nrcontrib -I -ab 1 -ad 256 -y 2 -e MF:1 -f reinhart.cal -b rbin -bn Nrbins -m sky_glow -m ground_glow\n"),
              std::string::npos) << o.out.substr(0, 400);
    EXPECT_EQ(headerValue(o.out, "NCOMP="), "3");
    EXPECT_EQ(headerValue(o.out, "NROWS="), "2");
    EXPECT_EQ(headerValue(o.out, "NCOLS="), "292");
    EXPECT_EQ(headerValue(o.out, "FORMAT="), "ascii");
    auto r = rows(o.out);
    ASSERT_EQ(r.size(), 2u);
    ASSERT_EQ(r[0].size(), 876u);
    // Each ray brings π/N to the bin it meets: a sensor facing up has π of sky, none of ground (Radiance's
    // ground bin 0 of the sky too); facing east, half of each.
    EXPECT_NEAR(sumOfFirstComponents(r[0], 0, 146), kPi, 1e-5);
    EXPECT_EQ(r[0][0], 0);
    EXPECT_EQ(sumOfFirstComponents(r[0], 146, 292), 0);
    EXPECT_NEAR(sumOfFirstComponents(r[1], 0, 146) + sumOfFirstComponents(r[1], 146, 292), kPi, 1e-5);
    EXPECT_NEAR(sumOfFirstComponents(r[1], 146, 292), kPi / 2, 0.05);
    EXPECT_EQ(o.out.substr(o.out.size() - 2), "\t\n");  // each component followed by a tab, as Radiance's
}

TEST(RcontribCli, ValuesAveragesAndBinaryRecords) {
    Case c("values", openSky(2), "0 0 0 0 0 1\n0 0 0 0 0 1\n0 0 0 0 0 1\n0 0 0 0 0 1\n");
    Output coefficients = c.run("-h -I -ab 1 -ad 64 -c 2 -m sky_glow");
    Output values = c.run("-h -I -ab 1 -ad 64 -c 2 -V -m sky_glow");
    ASSERT_EQ(coefficients.status, 0) << coefficients.err;
    ASSERT_EQ(values.status, 0) << values.err;
    EXPECT_EQ(coefficients.out, "3.141593e+00\t3.141593e+00\t3.141593e+00\t\n3.141593e+00\t3.141593e+00\t3.141593e+00\t\n");
    EXPECT_EQ(values.out, "6.283185e+00\t6.283185e+00\t6.283185e+00\t\n6.283185e+00\t6.283185e+00\t6.283185e+00\t\n");
    Output binary = c.run("-faf -I -ab 1 -ad 64 -y 4 -b 'if(Dx,1,0)' -bn 2 -m sky_glow");
    ASSERT_EQ(binary.status, 0) << binary.err;
    EXPECT_EQ(headerValue(binary.out, "FORMAT="), "float");
    EXPECT_EQ(headerValue(binary.out, "NROWS="), "4");
    EXPECT_EQ(headerValue(binary.out, "NCOLS="), "2");
    size_t data = binary.out.find("\n\n") + 2;
    ASSERT_EQ(binary.out.size() - data, 4u * 2 * 3 * sizeof(float));
    float first[6];
    std::memcpy(first, binary.out.data() + data, sizeof first);
    EXPECT_NEAR(first[0] + first[3], kPi, 1e-5);
    EXPECT_NEAR(first[0], kPi / 2, 0.1);  // the east half of the sky
}

// With spectral sampling (-cs) a record holds every band, as Radiance 6.1's: NCOMP and WAVELENGTH_SPLITS say so.
TEST(RcontribCli, SpectralCoefficientsHoldEveryBand) {
    Case c("spectral", openSky(), "0 0 0 0 0 1\n");
    Output o = c.run("-cs 5 -I -ab 1 -ad 64 -y 1 -m sky_glow");
    ASSERT_EQ(o.status, 0) << o.err;
    EXPECT_EQ(headerValue(o.out, "NCOMP="), "5");
    EXPECT_EQ(headerValue(o.out, "WAVELENGTH_SPLITS="), " 780 588 480 380");
    auto r = rows(o.out);
    ASSERT_EQ(r.size(), 1u);
    ASSERT_EQ(r[0].size(), 5u);
    for (double v : r[0]) EXPECT_NEAR(v, kPi, 1e-5);  // a grey sky: π in every band
}

// A reinhartb.cal of one's own, found first along RAYPATH, is the one that bins (Brume's own is computed
// natively, but only when it is the file read).
TEST(RcontribCli, AReinhartbCalOfOnesOwnBins) {
    Case c("own_cal", openSky(), "0 0 0 0 0 1\n");
    std::ofstream(c.dir / "reinhartb.cal") << "rbin = 0;\nNrbins = 146;\n";
    Output o = brume_test::runBrume("RAYPATH=. rcontrib -h -I -ab 1 -ad 64 -f reinhartb.cal -p MF=1 -bn Nrbins -b rbin "
                                    "-m sky_glow scene.rad < rays.txt", c.dir);
    ASSERT_EQ(o.status, 0) << o.err;
    auto r = rows("\n\n" + o.out);
    ASSERT_EQ(r.size(), 1u);
    ASSERT_EQ(r[0].size(), 3u * 146);
    EXPECT_NEAR(r[0][0], kPi, 1e-5);
    EXPECT_NEAR(sumOfFirstComponents(r[0], 0, 146), kPi, 1e-5);
}

// Contributions past a modifier's last bin are left out with a warning, as in Radiance.
TEST(RcontribCli, BinsPastTheLastAreLeftOutWithAWarning) {
    Case c("past", openSky(), "0 0 0 0 0 1\n");
    Output o = c.run("-h -I -ab 1 -ad 64 -b 'if(Dx,1,0)' -m sky_glow");
    ASSERT_EQ(o.status, 0) << o.err;
    EXPECT_NE(o.err.find("contributions fell past their modifier's last bin and were ignored"), std::string::npos) << o.err;
    auto r = rows("\n\n" + o.out);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_NEAR(r[0][0], kPi / 2, 0.1);  // the west half of the sky only
}

// -fc with -x and -y: each bin's file a picture, as Radiance's rcontrib writes it (an image-based view matrix:
// vwrays' rays, a picture per window bin): NROWS= the pixels, no NCOLS=, the resolution line after the
// header, RGBE pixels that Brume's picture reader (and Radiance's) reads back. Six rays under an open sky of
// radiance 1, its bins split at Dx = 0.5: each ray up 1 in its bin, 0 in the other; each ray down 0.
TEST(RcontribCli, RgbeOutputWritesAPicturePerBin) {
    Case c("rgbe", openSky(), "0 0 0 0 0 1\n0 0 0 0 0 -1\n0 0 0 1 0 .5\n0 0 0 1 0 -.5\n0 0 0 0 1 .1\n0 0 0 0 1 -.1\n");
    Output o = c.run("-fac -x 3 -y 2 -ab 0 -o 'bin%d.hdr' -bn 2 -b 'if(Dx-.5,1,0)' -m sky_glow");
    ASSERT_EQ(o.status, 0) << o.err;
    EXPECT_EQ(o.out, "");
    for (int b : {0, 1}) {
        std::string file = (c.dir / ("bin" + std::to_string(b) + ".hdr")).string();
        std::string text = slurp(file);
        EXPECT_EQ(headerValue(text, "NROWS="), "6");
        EXPECT_EQ(headerValue(text, "NCOLS="), "");
        EXPECT_EQ(headerValue(text, "FORMAT="), "32-bit_rle_rgbe");
        EXPECT_NE(text.find("\n\n-Y        2 +X        3\n"), std::string::npos);
        brume::Picture p = brume::readPicture(file);
        ASSERT_EQ(p.width, 3);
        ASSERT_EQ(p.height, 2);
        const int binOf[6] = {0, -1, 1, -1, 0, -1};  // each ray's bin, -1: it meets the ground
        // RGBE keeps 8 bits of mantissa, read back at the middle of its step (1 reads 1.0039).
        for (int i = 0; i < 6; ++i) EXPECT_NEAR(p.pixels[3 * i], binOf[i] == b ? 1 : 0, 0.008) << "bin " << b << " ray " << i;
    }
    Output bad = c.run("-fcc -o x.hdr -m sky_glow");
    EXPECT_NE(bad.status, 0);
    EXPECT_NE(bad.err.find("Illegal i/o format: -fcc"), std::string::npos) << bad.err;
}

TEST(RcontribCli, SameRecordsOnAnyNumberOfThreads) {
    std::string rays;
    for (int i = 0; i < 40; ++i) rays += std::to_string(0.1 * i) + " 0 0 0 " + std::to_string(0.05 * i) + " 1\n";
    Case c("threads", openSky() + "grey polygon wall 0 0 12 -2 1 -1 2 1 -1 2 1 3 -2 1 3\n", rays);
    std::string args = std::string("-u- -I -ab 3 -ad 64 -faf ") + kReinhart + " -m sky_glow -m ground_glow";
    Output one = c.run("-n 1 " + args), two = c.run("-n 2 " + args);
    ASSERT_EQ(one.status, 0) << one.err;
    EXPECT_EQ(one.out.substr(one.out.find("\n\n")), two.out.substr(two.out.find("\n\n")));
}

// Shared bounces (-aS, on by default) hand each first bounce's continuation to its cell: what the paths carry
// must survive the hand-over. Sensors facing down over a wide grey ground (diffuse reflectance 0.5) under an
// open sky of radiance 2: every first bounce is on the ground, and every continuation escapes to the sky, so
// each sensor's coefficients sum to 0.5π whatever the sampling (its sky bins, float rounding: 1e-4), and its
// contributions (-V) to π, with and without sharing, one ray a record or the mean of two (-c 2); the bins
// alone differ with the sampling, and sharing changes them (the cells' rays are not the points' own).
TEST(RcontribCli, SharedBouncesKeepWhatThePathsCarry) {
    std::string rays;
    for (int i = 0; i < 24; ++i) rays += std::to_string(0.3 * i) + " " + std::to_string(0.1 * (i % 5)) + " 1 0 0 -1\n";
    Case c("shared", openSky(2) + "grey polygon ground 0 0 12 -1e4 -1e4 0 1e4 -1e4 0 1e4 1e4 0 -1e4 1e4 0\n", rays);
    std::map<std::string, std::string> outs;
    for (std::string options : {"", "-aS 0", "-c 2", "-V", "-aS 0.5 -ab 4"}) {
        Output o = c.run("-u- -I -ab 2 -ad 64 " + options + " " + kReinhart + " -m sky_glow -m ground_glow");
        ASSERT_EQ(o.status, 0) << options << ": " << o.err;
        auto r = rows(o.out);
        ASSERT_EQ(r.size(), options == "-c 2" ? 12u : 24u) << options;
        for (const auto& row : r) {
            ASSERT_EQ(row.size(), 2u * 3 * 146) << options;  // each glow's 146 bins (reinhart.cal's 0: below)
            EXPECT_NEAR(sumOfFirstComponents(row, 0, 146), options == "-V" ? kPi : kPi / 2, 1e-4) << options;
            EXPECT_NEAR(sumOfFirstComponents(row, 146, 292), 0, 1e-6) << options;  // hidden by the ground
        }
        outs[options] = o.out;
    }
    EXPECT_NE(outs[""], outs["-aS 0"]);
    Output bad = c.run("-I -aS 2 -ab 2 -m sky_glow");
    EXPECT_NE(bad.status, 0);
    EXPECT_NE(bad.err.find("-aS: a fraction from 0 to 1 is expected"), std::string::npos) << bad.err;
}

// rtrace's sensors share bounces as rcontrib's do (-aS, on by default): the same cells, seeds and paths, so a
// sensor's contributions (-V) over every source of a daylit office sum to rtrace's value of it, to float
// rounding (1e-4 relative; a few thousand terms), on any number of threads, given rtrace rcontrib's -dt 0 and
// no bounces past -ab (-al+); with -aS 0 rtrace's sensors take the cache's records.
TEST(RcontribCli, SensorsContributionsSumToRtracesSharedValue) {
    fs::path dir = brume_test::scratchDir("rcontrib_rtrace_shared");
    std::ofstream(dir / "sky.rad") << "!gendaylit 6 21 12.5 -a 41.98 -o 87.92 -m 90 -W 800 100\n"
                                      "skyfunc glow skyglow 0 0 4 1 1 1 0\nskyglow source sky 0 0 4 0 0 1 180\n"
                                      "skyfunc glow groundglow 0 0 4 1 1 1 0\ngroundglow source ground 0 0 4 0 0 -1 180\n";
    std::string scene = "'" + (kData / "materials.rad").string() + "' '" + (kData / "office.rad").string() + "' sky.rad < '" +
                        (kData / "grid16.pts").string() + "'";
    std::string options = "-u- -h -I -ab 3 -ad 256 ";
    Output values = brume_test::runBrume("rtrace -n 2 -al+ -dt 0 " + options + scene, dir);
    Output oneThread = brume_test::runBrume("rtrace -n 1 -al+ -dt 0 " + options + scene, dir);
    Output cached = brume_test::runBrume("rtrace -n 2 -al+ -dt 0 -aS 0 " + options + scene, dir);
    Output parts = brume_test::runBrume("rcontrib -n 2 -V " + options + "-m solar -m skyglow -m groundglow " + scene, dir);
    ASSERT_EQ(values.status, 0) << values.err;
    ASSERT_EQ(parts.status, 0) << parts.err;
    EXPECT_EQ(values.out, oneThread.out);
    EXPECT_NE(values.out, cached.out);
    std::istringstream v(values.out), p(parts.out);
    int sensors = 0;
    for (std::string vl, pl; std::getline(v, vl) && std::getline(p, pl); ++sensors) {
        std::istringstream vw(vl), pw(pl);
        double value[3], sum[3] = {0, 0, 0}, x;
        vw >> value[0] >> value[1] >> value[2];
        for (int k = 0; pw >> x; ++k) sum[k % 3] += x;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], value[c], 1e-4 * value[c]) << "sensor " << sensors << " channel " << c;
    }
    EXPECT_EQ(sensors, 16);
}

TEST(RcontribCli, FilesPerModifierAndPerBin) {
    Case c("files", openSky(), "0 0 0 0 0 1\n0 0 0 1 0 0\n");
    Output o = c.run("-I -ab 1 -ad 64 -o o_%s.txt -b 'if(Dx,1,0)' -bn 2 -m sky_glow -m ground_glow");
    ASSERT_EQ(o.status, 0) << o.err;
    EXPECT_EQ(o.out, "");
    std::string sky = slurp(c.dir / "o_sky_glow.txt"), ground = slurp(c.dir / "o_ground_glow.txt");
    EXPECT_EQ(headerValue(sky, "MODIFIER="), "sky_glow");
    EXPECT_EQ(headerValue(ground, "MODIFIER="), "ground_glow");
    EXPECT_EQ(headerValue(sky, "NCOLS="), "2");
    EXPECT_EQ(rows(sky).size(), 2u);
    Output again = c.run("-I -ab 1 -ad 64 -o o_%s.txt -m sky_glow");
    EXPECT_NE(again.status, 0);
    EXPECT_NE(again.err.find("o_sky_glow.txt: exists (-fo to overwrite it)"), std::string::npos) << again.err;
    EXPECT_EQ(slurp(c.dir / "o_sky_glow.txt"), sky);
    // -o applies to the modifiers after it, as in Radiance: the sky to the standard output, the ground to a file.
    Output split = c.run("-fo -I -ab 1 -ad 64 -m sky_glow -o g.txt -m ground_glow");
    ASSERT_EQ(split.status, 0) << split.err;
    EXPECT_EQ(headerValue(split.out, "NCOLS="), "1");
    EXPECT_EQ(headerValue(split.out, "MODIFIER="), "");
    EXPECT_EQ(headerValue(slurp(c.dir / "g.txt"), "MODIFIER="), "ground_glow");
    EXPECT_EQ(rows(slurp(c.dir / "g.txt")).size(), 2u);
    Output perBin = c.run("-fo -I -ab 1 -ad 64 -o b_%s_%02d.txt -b 'if(Dx,1,0)' -bn 2 -m sky_glow");
    ASSERT_EQ(perBin.status, 0) << perBin.err;
    std::string bin1 = slurp(c.dir / "b_sky_glow_01.txt");
    EXPECT_EQ(headerValue(bin1, "BIN="), "1");
    EXPECT_EQ(headerValue(bin1, "NCOLS="), "1");
    EXPECT_TRUE(fs::exists(c.dir / "b_sky_glow_00.txt"));
    for (const auto& entry : fs::directory_iterator(c.dir))
        EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
}

TEST(RcontribCli, BadInputIsNamedAndWritesNothing) {
    Case c("media", openSky() + "void mist fog 0 0 3 .1 .1 .1\nfog sphere cloud 0 0 4 0 0 0 1\n", "0 0 0 0 0 1\n");
    Case clear("bad", openSky(), "0 0 0 0 0 1\n1 2\n");
    Case one("bad_one", openSky(), "0 0 0 0 0 1\n");
    struct Bad {
        const Case& where;
        std::string args, message;
    } cases[] = {
        {clear, "-I -m nothing", "modifier 'nothing' is not in the scene"},
        {clear, "-I -m grey", "modifier 'grey' (plastic) is no light source"},
        {clear, "-I", "no modifiers given (-m or -M)"},
        {clear, "-I -o out_%x.txt -m sky_glow", "only %s (the modifier), %d (the bin) and %% may be used"},
        {clear, "-I -b 2 -m sky_glow", "illegal non-zero constant for bin (2)"},
        {clear, "-I -e MF:1 -b rbin -bn 0 -f reinhart.cal -m sky_glow", "illegal bin count for modifier 'sky_glow'"},
        {clear, "-I -c 0 -m sky_glow", "-c: Brume accumulates one ray or more"},
        {clear, "-I -fcc -m sky_glow", "Illegal i/o format: -fcc"},
        {clear, "-I -M missing.txt", "missing.txt: cannot open modifier file"},
        {clear, "-I -m sky_glow -m sky_glow", "duplicate modifier 'sky_glow'"},
        {clear, "-I -o f_%s.txt -m sky_glow", "(stdin):2: 2 numbers, a ray needs 6"},
        {c, "-I -m sky_glow", "participating media (smoke, mist, -me) are not supported by rcontrib yet"},
        {one, "-I -o 'x%' -m sky_glow", "-o x%: a '%' ends the pattern"},
        {one, "-I -o '!cat' -m sky_glow", "-o !cat: commands as outputs are not supported"},
        {one, "-I -c 2 -m sky_glow", "(stdin): input ends within a record (-c 2)"},
    };
    for (const Bad& b : cases) {
        Output o = b.where.run(b.args);
        EXPECT_NE(o.status, 0) << b.args;
        EXPECT_NE(o.err.find(b.message), std::string::npos) << b.args << ": " << o.err;
        EXPECT_EQ(o.err.find("rcontrib: "), 0u) << o.err;
    }
    EXPECT_FALSE(fs::exists(clear.dir / "f_sky_glow.txt"));  // the bad ray came after a good one: nothing kept
}

// Each row's mean of an ASCII matrix after its header.
std::vector<double> rowMeans(const std::string& text) {
    std::vector<double> means;
    for (const std::vector<double>& r : rows(text)) {
        double s = 0;
        for (double v : r) s += v;
        if (!r.empty()) means.push_back(s / r.size());
    }
    return means;
}

// Each sensor's value (a whole-year or many-hour mean) within `each` of the reference's, their mean relative
// error within `mean`.
void expectSensorsAgree(const std::vector<double>& brume, const std::vector<double>& reference, double each, double mean,
                        const std::string& label) {
    ASSERT_EQ(brume.size(), reference.size()) << label;
    double meanError = 0;
    for (size_t i = 0; i < brume.size(); ++i) {
        double e = brume[i] / reference[i] - 1;
        EXPECT_LT(std::abs(e), each) << label << "sensor " << i << ": " << brume[i] << " lx, Radiance " << reference[i];
        meanError += e / double(brume.size());
    }
    EXPECT_LT(std::abs(meanError), mean) << label << meanError;
}

// Column `column` (from 0) of the lines of a file that are not comments.
std::vector<double> columnOf(const fs::path& path, int column) {
    std::vector<double> out;
    std::ifstream in(path);
    for (std::string l; std::getline(in, l);) {
        if (l.empty() || l[0] == '#') continue;
        std::istringstream w(l);
        double v = 0;
        for (int k = 0; k <= column; ++k) w >> v;
        out.push_back(v);
    }
    return out;
}

// The direct sun's matrix as Honeybee makes it: gendaymtx -D writes a light source per sun position (its
// modifier in suns.mod), rcontrib -V -ab 0 gives each sensor each sun's illuminance. Under an open sky with
// nothing in the way a sensor facing up gets L Ω cosθ from each (the disc's few samples: within 0.3 %).
TEST(RcontribCli, TheDirectSunsMatrixHasEachSunsIlluminance) {
    Case c("suns", "", "0 0 0 0 0 1\n");
    std::string line = "gendaymtx -D suns.rad -M suns.mod -O0 -n -r 0.0 '" + (fs::path(BRUME_TEST_DATA) / "daymtx/chicago48.wea").string() +
                       "' > /dev/null && rcontrib -I -V -ab 0 -faa -y 1 -M suns.mod suns.rad < rays.txt";
    Output o = brume_test::runBrume(line, c.dir);
    ASSERT_EQ(o.status, 0) << o.err;
    std::vector<double> row = rows(o.out).at(0);
    std::ifstream suns(c.dir / "suns.rad");
    std::vector<double> expected;
    for (std::string word; suns >> word;) {
        if (word != "light") continue;
        std::string name, zero;
        double r, g, b, x, y, z, angle;
        suns >> name >> zero >> zero >> zero >> r >> g >> b >> name >> name >> name >> zero >> zero >> zero >> x >> y >> z >> angle;
        double omega = 2 * kPi * (1 - std::cos(angle / 2 * kPi / 180));
        expected.push_back(r * omega * z / std::sqrt(x * x + y * y + z * z));
    }
    ASSERT_EQ(row.size(), 3 * expected.size());
    ASSERT_GT(expected.size(), 10u);
    for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(row[3 * i], expected[i], 3e-3 * expected[i]) << "sun " << i;
}

// Radiance's rfluxmtx, verbose, for bench/annual's sky (Honeybee's sky.dome: a uniform ground, Tregenza's sky):
// the rcontrib options it runs, word for word; Brume's rfluxmtx says the same and gives what rcontrib gives
// with them.
const char* kSkyReceivers =
    "-bn 1 -b 0 -m ground_glow -f reinhartb.cal -p MF=1,rNx=0,rNy=0,rNz=-1,Ux=0,Uy=1,Uz=0,RHS=+1 -bn Nrbins -b rbin -m sky_glow";

TEST(RfluxmtxCli, RunsRcontribWithTheReceiversBinsAsRadiances) {
    Case c("flux", openSky(), "0 0 0 0 0 1\n0 0 0 1 0 0\n");
    fs::copy_file(kData / "sky.rad", c.dir / "sky.dome", fs::copy_options::overwrite_existing);
    std::ofstream(c.dir / "ground.rad") << "void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey ring floor 0 0 8 0 0 -.1 0 0 1 0 5\n";
    Output flux = brume_test::runBrume("rfluxmtx -v -u- -I -ab 2 -ad 64 -y 2 - sky.dome ground.rad < rays.txt", c.dir);
    ASSERT_EQ(flux.status, 0) << flux.err;
    EXPECT_EQ(flux.err, std::string("rfluxmtx: running: rcontrib -u- -I -ab 2 -ad 64 -y 2 ") + kSkyReceivers +
                            " ground.rad sky.dome\n");
    Output direct = brume_test::runBrume(std::string("rcontrib -u- -I -ab 2 -ad 64 -y 2 ") + kSkyReceivers +
                                             " ground.rad sky.dome < rays.txt", c.dir);
    ASSERT_EQ(direct.status, 0) << direct.err;
    EXPECT_EQ(headerValue(flux.out, "NCOLS="), "146");
    EXPECT_EQ(flux.out.substr(flux.out.find("\n\n")), direct.out.substr(direct.out.find("\n\n")));
    std::ofstream(c.dir / "windows.rad") << "#@rfluxmtx h=u\nvoid glow win_glow 0 0 4 1 1 1 0\n"
                                            "win_glow polygon win 0 0 12 0 0 1  1 0 1  1 1 1  0 1 1\n"
                                            "#@rfluxmtx h=-r2 u=+Z\nvoid glow wall_glow 0 0 4 1 1 1 0\n"
                                            "wall_glow polygon wall 0 0 12 0 2 0  0 2 1  1 2 1  1 2 0\n";
    Output windows = brume_test::runBrume("rfluxmtx -v -I -ab 1 -ad 16 -y 1 - windows.rad ground.rad < rays.txt", c.dir);
    ASSERT_EQ(windows.status, 0) << windows.err;
    EXPECT_NE(windows.err.find("-bn 1 -b 'if(-Dx*0-Dy*0-Dz*1,0,-1)' -m win_glow -f reinhartb.cal "
                               "-p MF=2,rNx=0,rNy=1,rNz=0,Ux=0,Uy=0,Uz=1,RHS=-1 -bn Nrbins -b rbin -m wall_glow"),
              std::string::npos) << windows.err;
    EXPECT_EQ(headerValue(windows.out, "NCOLS="), "578");
}

TEST(RfluxmtxCli, BadReceiversAreNamed) {
    Case c("flux_bad", openSky(), "0 0 0 0 0 1\n");
    struct Bad {
        std::string receivers, args, message;
    } cases[] = {
        {"#@rfluxmtx h=sc4\nvoid glow g 0 0 4 1 1 1 0\ng polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n", "-I - r.rad scene.rad",
         "hemisphere sampling h=sc4 is not supported yet"},
        {"#@rfluxmtx h=kq\nvoid glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 90\n", "-I - r.rad scene.rad", "source 's' must be 180-degrees"},
        {"void glow g 0 0 4 1 1 1 0\ng polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n", "-I - r.rad scene.rad", "missing hemisphere sampling type"},
        {"#@rfluxmtx h=r\nvoid glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 90\n", "-I - r.rad scene.rad", "source 's' must be 180-degrees"},
        {"#@rfluxmtx h=u w=1\nvoid glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 180\n", "-I - r.rad scene.rad", "r.rad:1: bad parameter string"},
        {"#@rfluxmtx h=u\nvoid glow g 0 0 4 1 1 1 0\ng polygon p 0 0 7 0 0 0 1 0 0 0\n", "-I - r.rad scene.rad", "r.rad:3: bad argument count"},
        {"void glow g 0 0 4 1 1 1 0\n", "-I - r.rad scene.rad", "r.rad: no receiver surfaces"},
        {"#@rfluxmtx h=u\nvoid glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 180\n", "r.rad r.rad scene.rad", "r.rad:3: cannot use source 's' as a sender"},
        {"#@rfluxmtx h=u\nvoid glow g 0 0 4 1 1 1 0\ng polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n", "-I r.rad r.rad scene.rad",
         "-i, -I supported for pass-through only"},
        {"#@rfluxmtx h=u u=W\nvoid glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 180\n", "-I - r.rad scene.rad", "r.rad:1: bad up direction u=W"},
        {"#@rfluxmtx h=u\n!cat other.rad\n", "-I - r.rad scene.rad", "r.rad:2: commands in receiver files are not supported"},
        {"#@rfluxmtx h=u\nvoid glow g 0 0 4 1 1 1 0\ng polygon p 0 0 9 0 0 0 1 0 0 zero 1 0\n", "-I - r.rad scene.rad",
         "r.rad:3: bad real argument 'zero' of 'p'"},
        {"", "-I - missing.rad scene.rad", "missing.rad: cannot open receiver file"},
        {"#@rfluxmtx h=u\nvoid glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 180\n", "-I - r.rad scene.rad -i", "-i: missing system octree"},
        {"#@rfluxmtx h=u\nvoid glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 180\n", "-I - r.rad -ab 2 scene.rad", "option -ab after the sender and receiver"},
        {"#@rfluxmtx h=u\nvoid glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 180\n", "-I -", "missing receiver file"},
    };
    for (const Bad& b : cases) {
        std::ofstream(c.dir / "r.rad") << b.receivers;
        Output o = brume_test::runBrume("rfluxmtx " + b.args + " < rays.txt", c.dir);
        EXPECT_NE(o.status, 0) << b.receivers;
        EXPECT_NE(o.err.find(b.message), std::string::npos) << b.receivers << ": " << o.err;
        EXPECT_EQ(o.out, "");
    }
}

// A sender's bins and a receiver's bins of the same basis in the same frame are the same directions: a sender
// facing up under an open sky whose hemisphere is binned as it is sends every ray of a bin to that bin (rays
// inside their patches, so no rounding at the edges: the identity to the last digit), in either hand.
TEST(RfluxmtxCli, ASendersBinsReachTheSameBinsOfTheSky) {
    Case c("flux_identity", "void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey polygon far 0 0 12 50 50 -9 50 51 -9 51 51 -9 51 50 -9\n", "");
    for (std::string h : {"kf", "kh", "kq", "-kf", "r1", "-r2"}) {
        std::ofstream(c.dir / "sender.rad") << "#@rfluxmtx h=" << h << " u=Y\nvoid polygon s 0 0 12 0 0 0  0 1 0  1 1 0  1 0 0\n";
        std::ofstream(c.dir / "sky.rad") << "#@rfluxmtx h=" << h << " u=Y\nvoid glow sky_glow 0 0 4 1 1 1 0\n"
                                         << "sky_glow source sky 0 0 4 0 0 1 180\n";
        Output o = brume_test::runBrume("rfluxmtx -ab 0 -c 20 sender.rad sky.rad scene.rad", c.dir);
        ASSERT_EQ(o.status, 0) << o.err;
        std::vector<std::vector<double>> m = rows(o.out);
        size_t n = size_t(std::stoi(headerValue(o.out, "NROWS=")));
        EXPECT_EQ(headerValue(o.out, "NCOLS="), std::to_string(n)) << h;
        ASSERT_EQ(m.size(), n) << h;
        for (size_t r = 0; r < n; ++r)
            for (size_t col = 0; col < n; ++col) ASSERT_EQ(m[r][3 * col], r == col ? 1 : 0) << h << " row " << r << " column " << col;
    }
    // -v says the rcontrib command as Radiance's rfluxmtx runs it: its -c (10000 by default) and a row per bin.
    std::ofstream(c.dir / "sender.rad") << "#@rfluxmtx h=kq u=Y\nvoid polygon s 0 0 12 0 0 0  0 1 0  1 1 0  1 0 0\n";
    Output v = brume_test::runBrume("rfluxmtx -v -ab 0 sender.rad sky.rad scene.rad", c.dir);
    ASSERT_EQ(v.status, 0) << v.err;
    EXPECT_NE(v.err.find("rfluxmtx: running: rcontrib -ab 0 -c 10000 -f reinhartb.cal"), std::string::npos) << v.err;
    EXPECT_NE(v.err.find(" -m sky_glow -y 41 scene.rad sky.rad\nrfluxmtx: sampling 41 directions\n"), std::string::npos) << v.err;
}

// A sender of h=u sends its rays cosine-weighted: each of Reinhart's patches of an open sky takes the share
// of them its projected solid angle is of π, (Δφ/2)(sin² a₁ − sin² a₀)/π for a patch from altitude a₀ to a₁.
// 20000 rays, a patch's share p spread by √(p(1 − p)/20000) at most: within five of that.
TEST(RfluxmtxCli, AUniformSendersRaysReachEachPatchByItsProjectedSolidAngle) {
    Case c("flux_uniform", "void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey polygon far 0 0 12 50 50 -9 50 51 -9 51 51 -9 51 50 -9\n", "");
    std::ofstream(c.dir / "sender.rad") << "#@rfluxmtx h=u u=Y\nvoid polygon s 0 0 12 0 0 0  0 1 0  1 1 0  1 0 0\n";
    std::ofstream(c.dir / "sky.rad") << "#@rfluxmtx h=r1 u=Y\nvoid glow sky_glow 0 0 4 1 1 1 0\nsky_glow source sky 0 0 4 0 0 1 180\n";
    Output o = brume_test::runBrume("rfluxmtx -ab 0 -c 20000 sender.rad sky.rad scene.rad", c.dir);
    ASSERT_EQ(o.status, 0) << o.err;
    std::vector<std::vector<double>> m = rows(o.out);
    ASSERT_EQ(m.size(), 1u);
    ASSERT_EQ(m[0].size(), 3u * 145);
    const int perRow[8] = {30, 30, 24, 24, 18, 12, 6, 1};
    const double height = kPi / 2 / 7.5;
    double sum = 0;
    for (int row = 0, bin = 0; row < 8; ++row) {
        double a0 = row * height, a1 = std::min(kPi / 2, (row + 1) * height);
        double share = (kPi / perRow[row]) * (std::pow(std::sin(a1), 2) - std::pow(std::sin(a0), 2)) / kPi;
        for (int k = 0; k < perRow[row]; ++k, ++bin) {
            EXPECT_NEAR(m[0][3 * bin], share, 5 * std::sqrt(share * (1 - share) / 20000)) << "patch " << bin;
            sum += m[0][3 * bin];
        }
    }
    EXPECT_NEAR(sum, 1, 1e-5);
}

// The 3-phase method as Radiance's tutorials run it, on test/data/rfluxmtx/room.rad (a side-lit room whose
// window is the prismatic pane test/data/bsdf/prism_quarter.xml, Klems' quarter basis; a block across the
// street): the view matrix from 16 sensors to the window (h=kq), the daylight matrix from the window (h=-kq) to
// Tregenza's sky and the ground, dctimestep with the XML BSDF, over 48 hours of Chicago; each sensor's mean
// against Radiance's (three_phase_reference.txt: its own standard error 0.5 % or less, make_three_phase_reference.sh).
// At these settings Brume's sensors are 0.6-1.1 % RMS off it, the worst 1.5-2.9 %, the mean 0.7 % at most (four
// seeds): each within 6 %, their mean within 2 %.
TEST(RfluxmtxCli, TheThreePhaseMethodAgreesWithRadiance) {
    const fs::path flux = fs::path(BRUME_TEST_DATA) / "rfluxmtx";
    fs::path dir = brume_test::scratchDir("rfluxmtx_three_phase");
    for (const char* f : {"room.rad", "window_v.rad", "window_d.rad", "sensors.pts"})
        fs::copy_file(flux / f, dir / f, fs::copy_options::overwrite_existing);
    fs::copy_file(kData / "sky.rad", dir / "sky.rad", fs::copy_options::overwrite_existing);
    std::vector<double> reference = columnOf(flux / "three_phase_reference.txt", 0);
    ASSERT_EQ(reference.size(), 16u);
    std::string line = "gendaymtx -m 1 -of '" + (fs::path(BRUME_TEST_DATA) / "daymtx" / "chicago48.wea").string() +
                       "' > sky.smx && rfluxmtx -u- -I -ab 6 -ad 8192 -lw 1e-5 -y 16 - window_v.rad room.rad < sensors.pts > v.mtx && "
                       "rfluxmtx -u- -ab 2 -ad 512 -lw 1e-4 -c 1000 window_d.rad sky.rad room.rad > d.mtx && "
                       "dctimestep v.mtx '" + (fs::path(BRUME_TEST_DATA) / "bsdf" / "prism_quarter.xml").string() +
                       "' d.mtx sky.smx | rmtxop -fa - -c 47.4 119.9 11.6";
    Output o = brume_test::runBrume(line, dir);
    ASSERT_EQ(o.status, 0) << o.err;
    expectSensorsAgree(rowMeans(o.out), reference, 0.06, 0.02, "");
}

// A sender's hand, as Radiance's: the test room's window (window_d.rad) sends its bins' rays past a block off to
// one side (block_aside.rad), h=-kq and h=kq; each bin's share of rays that pass (its row's sum at -ab 0) against
// Radiance's (hand_reference.txt, -c 20000). The two hands differ by up to 0.99 in a bin; at -c 2000 a share spreads
// by 0.011 at most, Radiance's by 0.0035: each within 0.06 (five of both). Its rows are the same on 1 and 2 threads.
TEST(RfluxmtxCli, ASendersHandIsRadiances) {
    const fs::path flux = fs::path(BRUME_TEST_DATA) / "rfluxmtx";
    fs::path dir = brume_test::scratchDir("rfluxmtx_hand");
    fs::copy_file(flux / "window_d.rad", dir / "left.rad", fs::copy_options::overwrite_existing);
    std::string right = slurp(flux / "window_d.rad");
    right.replace(right.find("h=-kq"), 5, "h=kq");
    std::ofstream(dir / "right.rad") << right;
    std::vector<double> left = columnOf(flux / "hand_reference.txt", 0), rightShares = columnOf(flux / "hand_reference.txt", 1);
    ASSERT_EQ(left.size(), 41u);
    for (auto [file, reference] : {std::pair{"left.rad", &left}, std::pair{"right.rad", &rightShares}}) {
        Output o = brume_test::runBrume(std::string("rfluxmtx -h -ab 0 -c 2000 ") + file + " '" +
                                            (kData / "sky.rad").string() + "' '" + (flux / "block_aside.rad").string() + "'",
                                        dir);
        ASSERT_EQ(o.status, 0) << o.err;
        std::vector<std::vector<double>> m = rows("\n\n" + o.out);
        ASSERT_EQ(m.size(), 41u);
        for (size_t b = 0; b < 41; ++b)
            EXPECT_NEAR(sumOfFirstComponents(m[b], 0, 146), (*reference)[b], 0.06) << file << " bin " << b;
    }
    // A sender's rows are the same bytes on any number of threads at -u-.
    std::string rest = " -h -u- -ab 1 -ad 16 -c 50 left.rad '" + (kData / "sky.rad").string() + "' '" +
                       (flux / "block_aside.rad").string() + "'";
    Output one = brume_test::runBrume("rfluxmtx -n 1" + rest, dir), two = brume_test::runBrume("rfluxmtx -n 2" + rest, dir);
    ASSERT_EQ(one.status, 0) << one.err;
    EXPECT_EQ(rows("\n\n" + one.out).size(), 41u);
    EXPECT_EQ(one.out, two.out);
}

// The image-based 3-phase method: the view matrix as a picture per window bin (-fac with -x and -y), which
// dctimestep sums with T D sky into a picture, as Radiance's does (the same sum to the last bit on the same
// pictures); against the same rays' view matrix as numbers, the same seeds and paths: each pixel within 2 %
// (RGBE keeps 8 bits of mantissa per bin's picture: under 0.8 % each).
TEST(RfluxmtxCli, PicturesPerBinSumToTheViewMatrixsValues) {
    const fs::path flux = fs::path(BRUME_TEST_DATA) / "rfluxmtx";
    fs::path dir = brume_test::scratchDir("rfluxmtx_pictures");
    for (const char* f : {"room.rad", "window_v.rad", "window_d.rad"})
        fs::copy_file(flux / f, dir / f, fs::copy_options::overwrite_existing);
    fs::copy_file(kData / "sky.rad", dir / "sky.rad", fs::copy_options::overwrite_existing);
    std::ofstream rays(dir / "rays.txt");
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) rays << "2 4 1.5 " << (x - 1.5) * 0.4 << " -1 " << (1 - y) * 0.3 << "\n";
    rays.close();
    for (int steps : {1, 2}) {
        std::ofstream sky(dir / (steps == 1 ? "sky.vec" : "sky2.vec"));
        sky << "#?RADIANCE\nNROWS=146\nNCOLS=" << steps << "\nNCOMP=3\nFORMAT=ascii\n\n";
        for (int p = 0; p < 146; ++p)
            for (int t = 0; t < steps; ++t)  // the second step half the first
                sky << (10 + p % 7) / (t + 1.0) << " " << (11 + p % 5) / (t + 1.0) << " " << (12 + p % 3) / (t + 1.0)
                    << (t + 1 < steps ? "\t" : "\n");
    }
    const std::string xml = "'" + (fs::path(BRUME_TEST_DATA) / "bsdf" / "prism_quarter.xml").string() + "'";
    Output o = brume_test::runBrume(
        "rfluxmtx -u- -ab 0 -c 50 window_d.rad sky.rad room.rad > d.mtx && "
        "rfluxmtx -u- -fac -x 4 -y 3 -ab 1 -ad 64 -o 'w%03d.hdr' - window_v.rad room.rad < rays.txt && "
        "rfluxmtx -u- -faa -x 4 -y 3 -ab 1 -ad 64 - window_v.rad room.rad < rays.txt > v.mtx && "
        "dctimestep 'w%03d.hdr' " + xml + " d.mtx sky.vec > view.hdr && dctimestep -h v.mtx " + xml + " d.mtx sky.vec", dir);
    ASSERT_EQ(o.status, 0) << o.err;
    std::vector<std::vector<double>> values = rows("\n\n" + o.out);
    brume::Picture p = brume::readPicture((dir / "view.hdr").string());
    ASSERT_EQ(p.width, 4);
    ASSERT_EQ(p.height, 3);
    ASSERT_EQ(values.size(), 12u);
    int lit = 0;  // rays to the wall above the window see none of it (it is in the wall's plane): 0 both ways
    for (size_t i = 0; i < 12; ++i)
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(p.pixels[3 * i + c], values[i][c], 0.02 * values[i][c]) << "pixel " << i << " component " << c;
            lit += values[i][c] > 0;
        }
    EXPECT_GE(lit, 24);
    struct Refusal {
        std::string line, message;
    } refusals[] = {
        {"dctimestep 'w%03d.hdr' " + xml + " d.mtx sky.vec sky.vec", "one to four matrices"},
        {"dctimestep 'missing%03d.hdr' " + xml + " d.mtx sky.vec", "missing000.hdr"},
        {"dctimestep 'w%03d_%s.hdr' " + xml + " d.mtx sky.vec", "a picture pattern takes one %d (the bin) and %% only"},
        {"dctimestep 'w%03d.hdr' " + xml + " d.mtx 'w%03d.hdr'", "only the first matrix may be pictures by bin"},
        {"cp w000.hdr m000.hdr && rfluxmtx -u- -fac -x 2 -y 6 -ab 0 -o 'small%03d.hdr' - window_v.rad room.rad < rays.txt && "
         "for b in $(seq -w 1 40); do cp small0$b.hdr m0$b.hdr; done && dctimestep 'm%03d.hdr' " + xml + " d.mtx sky.vec",
         "m001.hdr: 2 by 6, not 4 by 3 as the first picture"},
    };
    for (const Refusal& r : refusals) {
        Output bad = brume_test::runBrume(r.line, dir);
        EXPECT_NE(bad.status, 0) << r.line;
        EXPECT_NE(bad.err.find(r.message), std::string::npos) << r.line << ": " << bad.err;
    }
    // Two time steps: a picture each, in files (-o with %d) or one after another in one stream, FRAME= in each.
    Output steps = brume_test::runBrume("dctimestep -o 'f%d.hdr' 'w%03d.hdr' " + xml + " d.mtx sky2.vec && "
                                        "dctimestep 'w%03d.hdr' " + xml + " d.mtx sky2.vec", dir);
    ASSERT_EQ(steps.status, 0) << steps.err;
    brume::Picture first = brume::readPicture((dir / "f0.hdr").string()), second = brume::readPicture((dir / "f1.hdr").string());
    for (size_t i = 0; i < first.pixels.size(); ++i)
        EXPECT_NEAR(second.pixels[i], first.pixels[i] / 2, 0.01 * first.pixels[i]) << i;
    EXPECT_NE(slurp(dir / "f1.hdr").find("FRAME=1\n"), std::string::npos);
    size_t frame0 = steps.out.find("FRAME=0\nFORMAT=32-bit_rle_rgbe\n\n-Y        3 +X        4\n");
    size_t frame1 = steps.out.find("FRAME=1\nFORMAT=32-bit_rle_rgbe\n\n-Y        3 +X        4\n");
    EXPECT_TRUE(frame0 != std::string::npos && frame1 != std::string::npos && frame0 < frame1);
    EXPECT_EQ(steps.out.rfind("#?RADIANCE"), 0u);  // one header
}

// Honeybee's 2-phase annual run (rfluxmtx with its sky.dome, rmtxop times gendaymtx's sky, to lux) on 16 sensors
// of bench/annual's office under Chicago's year, against Radiance's converged reference (ten runs at -ab 10
// -ad 50000, its own error 0.18 %). At -ab 7 -ad 2048 Brume's sensors spread about 1.6 % RMS from run to run
// with each first bounce's own path (-aS 0, Radiance's estimator), 0.8 % with shared bounces (the default;
// bench/annual.py), and -ab 7 leaves out about 0.1 %: each sensor within 8 % (five times the larger), their
// mean within 2 %, both ways.
TEST(RfluxmtxCli, AYearInASideLitOfficeAgreesWithRadiance) {
    fs::path dir = brume_test::scratchDir("rcontrib_office");
    fs::copy_file(kData / "sky.rad", dir / "sky.dome", fs::copy_options::overwrite_existing);
    std::vector<double> reference = columnOf(kData / "office_reference.txt", 3);
    ASSERT_EQ(reference.size(), 16u);
    for (std::string sharing : {"", "-aS 0 "}) {
        std::string line =
            "epw2wea '" + (kWeather / "chicago.epw").string() + "' chicago.wea && gendaymtx -m 1 -of chicago.wea > sky.smx && "
            "rfluxmtx -u- -I -aa 0.0 -ab 7 -ad 2048 -c 1 -faf -lw 1e-5 " + sharing + "-y 16 - sky.dome '" +
            (kData / "materials.rad").string() + "' '" + (kData / "office.rad").string() + "' < '" +
            (kData / "grid16.pts").string() + "' | rmtxop -fa - sky.smx -c 47.4 119.9 11.6";
        Output o = brume_test::runBrume(line, dir);
        ASSERT_EQ(o.status, 0) << o.err;
        expectSensorsAgree(rowMeans(o.out), reference, 0.08, 0.02, sharing);
    }
}

}  // namespace
