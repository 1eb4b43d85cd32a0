// The annual-daylight matrix tools as programs: gendaymtx, epw2wea, rmtxop and dctimestep against Radiance
// 6.1's outputs (test/data/daymtx, made by its make_radiance_outputs.sh): small cases word for word, whole
// years of the shared weather files by the CRC-32 of their binary data; and their errors.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "io/picture.h"
#include "spectrum/cie_tables.h"
#include "spectrum/colorimetry.h"
#include "same_words.h"

namespace {

namespace fs = std::filesystem;

using brume_test::Output;
using brume_test::slurp;

const fs::path kData = fs::path(BRUME_TEST_DATA) / "daymtx";
const fs::path kWeather = fs::path(BRUME_SHARED_DATA) / "weather";

// Runs a command line in `dir` with Brume's programs first on PATH (no globbing: rmtxop's '*').
Output runIn(const fs::path& dir, const std::string& line) {
    return brume_test::runCaptured("set -f; cd '" + dir.string() + "' && PATH='" + std::string(BRUME_BIN_DIR) + "':\"$PATH\" " + line,
                                   brume_test::scratchDir("daymtx"));
}

struct Split {
    std::vector<std::string> header;  // the lines that say what the data are
    std::string data;
};

// A header's lines but the ones that differ by program and run (the command, software and dates).
Split split(const std::string& text) {
    Split s;
    if (text.rfind("#?", 0) != 0) {
        s.data = text;
        return s;
    }
    size_t end = text.find("\n\n");
    std::istringstream lines(text.substr(0, end));
    for (std::string line; std::getline(lines, line);) {
        while (!line.empty() && line.back() == ' ') line.pop_back();  // FORMAT= padding
        bool command = line.rfind("gendaymtx", 0) == 0 || line.rfind("rmtxop", 0) == 0 || line.rfind("dctimestep", 0) == 0;
        bool stamp = line.rfind("SOFTWARE=", 0) == 0 || line.rfind("CAPDATE=", 0) == 0 || line.rfind("GMT=", 0) == 0;
        if (!command && !stamp && line.rfind("#?", 0) != 0) s.header.push_back(line);
    }
    s.data = text.substr(end + 2);
    return s;
}

// The CRC-32 and length of what follows a header.
std::string dataFingerprint(const std::string& bytes) {
    size_t end = bytes.find("\n\n");
    if (end == std::string::npos) return "no header";
    const auto* d = reinterpret_cast<const Bytef*>(bytes.data() + end + 2);
    size_t n = bytes.size() - end - 2;
    char out[64];
    std::snprintf(out, sizeof out, "%08lx %zu", crc32(0, d, uInt(n)), n);
    return out;
}

struct Refusal {
    const char* command;
    const char* message;  // what the standard error starts with
};

// Each command fails with status 1, its message on the standard error and nothing on the standard output.
void expectRefused(const fs::path& dir, std::initializer_list<Refusal> cases) {
    for (const Refusal& c : cases) {
        Output r = runIn(dir, c.command);
        EXPECT_EQ(r.status, 1) << c.command;
        EXPECT_TRUE(r.out.empty()) << c.command << "\n" << r.out.substr(0, 200);
        EXPECT_EQ(r.err.rfind(c.message, 0), 0u) << c.command << "\n" << r.err;
    }
}

// daymetrics' hand-made year in `dir`: the sensor of AnnualMetrics' test (Honeybee's numbers) and a brighter
// one over nine hours (ill.mtx, the columns' hours in hours.txt), ten occupied hours (schedule.txt) and the
// direct sun of three of them at the first sensor (sun.mtx).
void writeSensorYear(const fs::path& dir) {
    std::ofstream(dir / "ill.mtx") << "#?RADIANCE\nNROWS=2\nNCOLS=9\nNCOMP=1\nFORMAT=ascii\n\n"
                                          "0 150 299.99 300 600 3000 3000.5 50 5000\n"
                                          "400 400 400 400 400 400 400 400 400\n";
    std::ofstream(dir / "sun.mtx") << "#?RADIANCE\nNROWS=2\nNCOLS=9\nNCOMP=1\nFORMAT=ascii\n\n"
                                          "0 0 0 0 0 0 1001 1001 1001\n0 0 0 0 0 0 0 0 0\n";
    std::ofstream hours(dir / "hours.txt");
    for (int h = 8; h <= 16; ++h) hours << h + 0.5 << "\n";
    hours.close();
    std::ofstream schedule(dir / "schedule.txt");
    for (int h = 0; h < 8760; ++h) schedule << ((h >= 8 && h <= 15) || h == 20 || h == 21 ? 1 : 0) << "\n";
    schedule.close();
}

}  // namespace

// Every command line of commands.txt: gendaymtx's options (-d, -s, -O1, -r, -5, -A, -u, -i, -g/-c, -h, -D -n)
// on two days of Chicago's year, rmtxop's products, sums, element-wise products and quotients, transposes,
// transforms (symbolic ones among them) and scales, a Klems BSDF's transmission matrix, dctimestep's products (DC
// times sky, V times a BSDF's T times D times sky). Radiance's to its printed precision, but
// rmtxop's sums, which Radiance takes in single precision (3e-7: two units of a float), and dctimestep's, which
// Radiance's AVX2 code takes in another order than its own rmtxop (7e-7 apart): 2e-6 there.
TEST(DaymtxCli, OutputMatchesRadianceToPrintedPrecision) {
    for (const char* program : {"gendaymtx", "rmtxop", "dctimestep"})
        ASSERT_TRUE(fs::exists(fs::path(BRUME_BIN_DIR) / program)) << program;
    std::ifstream commands(kData / "commands.txt");
    std::string line;
    int n = 0;
    while (std::getline(commands, line)) {
        char name[16];
        std::snprintf(name, sizeof name, "%02d.txt", ++n);
        Output brume = runIn(kData, line);
        ASSERT_EQ(brume.status, 0) << line << "\n" << brume.err;
        Split b = split(brume.out), r = split(slurp(kData / "radiance" / name));
        ASSERT_FALSE(r.data.empty()) << name;
        EXPECT_EQ(b.header, r.header) << line;
        double relative = line.rfind("dctimestep", 0) == 0 ? 2e-6 : line.rfind("rmtxop", 0) == 0 ? 3e-7 : 0;
        brume_test::expectSameWords(b.data, r.data, line, relative);
    }
    EXPECT_EQ(n, 24);
}

// rmtxop's symbolic components of spectral matrices (9 bands over 780-380 nm, 6 over 720-400) against Radiance
// 6.1's (spectral_symbols.txt, made by make_spectral_symbols.sh). Radiance rounds each band's edges to whole
// nanometres, Brume does not: a band's weight may differ by the curve's area within 1 nm of each of its two edges,
// at most 3.4 % of the curve's whole area (z-bar is the steepest, 1.7 % a nm), R, G and B likewise; a white
// spectrum's and a smooth one's totals agree within 0.2 % (the tables differ in the fourth digit where a range
// cuts a curve, 400 and 720 nm) and 1 %.
TEST(DaymtxCli, RmtxopTurnsSpectraIntoRadiancesSymbolicComponents) {
    std::ifstream in(kData / "spectral_symbols.txt");
    std::string line;
    int rows = 0;
    while (std::getline(in, line)) {
        if (line[0] == '#') continue;
        std::istringstream words(line);
        int bands;
        std::string symbol;
        words >> bands >> symbol;
        std::vector<double> radiance, brume;
        for (double w; words >> w;) radiance.push_back(w);
        const std::string command = "rmtxop -fa -c " + symbol + " spectral" + std::to_string(bands) + ".mtx";
        Output r = runIn(kData, command);
        ASSERT_EQ(r.status, 0) << command << "\n" << r.err;
        std::istringstream values(split(r.out).data);
        for (double w; values >> w;) brume.push_back(w);
        ASSERT_EQ(brume.size(), size_t(bands)) << command;
        ASSERT_EQ(radiance.size(), size_t(bands)) << command;
        double area = 0, white[2] = {0, 0}, smooth[2] = {0, 0};
        for (int i = 0; i < bands; ++i) {
            area += std::abs(radiance[i]);
            double ramp = 1 + 0.5 * i / (bands - 1);  // rising toward the blue, as daylight's does
            white[0] += brume[i], white[1] += radiance[i];
            smooth[0] += brume[i] * ramp, smooth[1] += radiance[i] * ramp;
        }
        for (int i = 0; i < bands; ++i) EXPECT_NEAR(brume[i], radiance[i], 0.034 * area) << command << " band " << i;
        EXPECT_NEAR(white[0], white[1], 2e-3 * std::abs(white[1]) + 1e-6) << command;
        EXPECT_NEAR(smooth[0], smooth[1], 0.01 * std::abs(smooth[1]) + 1e-6) << command;
        ++rows;
    }
    EXPECT_EQ(rows, 22);
}

// epw2wea writes Radiance's .wea byte for byte: chicago48.wea is Radiance's header and two days of it.
TEST(DaymtxCli, Epw2weaWritesRadiancesWea) {
    if (!fs::exists(kWeather / "chicago.epw")) GTEST_SKIP() << "no shared weather data";
    Output r = runIn(kData, "epw2wea '" + (kWeather / "chicago.epw").string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    std::istringstream expected(slurp(kData / "chicago48.wea")), got(r.out);
    std::vector<std::string> all;
    for (std::string l; std::getline(got, l);) all.push_back(l);
    ASSERT_EQ(all.size(), 8766u);
    std::string l;
    for (int i = 0; i < 6 && std::getline(expected, l); ++i) EXPECT_EQ(all[i], l);
    // June 21st is day 172: records 171 × 24 on; December 21st, day 355.
    for (int i = 0; i < 48 && std::getline(expected, l); ++i) EXPECT_EQ(all[6 + (i < 24 ? 171 * 24 + i : 354 * 24 + i - 24)], l);
}

// Whole years: Brume's epw2wea, then gendaymtx -of, give Radiance's bytes (Tregenza's and Reinhart's
// patches, the sun alone at -m 4, the sky alone, solar units, a rotation, the 5-phase sun, the mean sky,
// sun hours only, a year with its times in UTC, an EPW file read directly with its dew points).
TEST(DaymtxCli, WholeYearsMatchRadianceByteForByte) {
    if (!fs::exists(kWeather / "chicago.epw")) GTEST_SKIP() << "no shared weather data";
    fs::path scratch = brume_test::scratchDir("daymtx_years");
    ASSERT_EQ(runIn(scratch, "epw2wea '" + (kWeather / "chicago.epw").string() + "' chicago.wea").status, 0);
    ASSERT_EQ(runIn(scratch, "epw2wea '" + (kWeather / "tmy_45.000_8.000_2005_2023.epw").string() + "' tmy45.wea").status, 0);
    fs::copy_file(kWeather / "chicago.epw", scratch / "chicago.epw", fs::copy_options::overwrite_existing);
    std::ifstream list(kData / "fingerprints.txt");
    std::string line;
    int n = 0;
    while (std::getline(list, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::string crc, bytes;
        std::istringstream words(line);
        words >> crc >> bytes;
        std::string command;
        std::getline(words >> std::ws, command);
        Output r = runIn(scratch, command.insert(command.rfind(' '), " -of"));
        ASSERT_EQ(r.status, 0) << command << "\n" << r.err;
        EXPECT_EQ(dataFingerprint(r.out), crc + " " + bytes) << command;
        ++n;
    }
    EXPECT_EQ(n, 12);
}

// Bad input: the file and line, status 1, nothing on the standard output.
TEST(DaymtxCli, BadInputIsNamedAndWritesNothing) {
    fs::path scratch = brume_test::scratchDir("daymtx_errors");
    std::ofstream(scratch / "short.wea") << "place X_Y\nlatitude 40\nlongitude 80\n";
    std::ofstream(scratch / "units.wea") << "place X_Y\nlatitude 40\nlongitude 80\ntime_zone 75\nsite_elevation 0\nweather_data_file_units 7\n";
    std::ofstream(scratch / "record.wea") << "place X_Y\nlatitude 40\nlongitude 80\ntime_zone 75\nsite_elevation 0\n"
                                             "weather_data_file_units 1\n6 21 12.5 800 100\n6 21 13.5 eight 100\n";
    std::ofstream(scratch / "date.wea") << "place X_Y\nlatitude 40\nlongitude 80\ntime_zone 75\nsite_elevation 0\n"
                                           "weather_data_file_units 1\n2 30 12.5 800 100\n";
    std::ofstream(scratch / "latitude.wea") << "place X_Y\nlatitude 95\nlongitude 80\ntime_zone 75\nsite_elevation 0\nweather_data_file_units 1\n";
    std::ofstream(scratch / "a.mtx") << "#?RADIANCE\nNROWS=2\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n1 2 3\n";
    std::ofstream(scratch / "b.mtx") << "#?RADIANCE\nNROWS=3\nNCOLS=1\nNCOMP=1\nFORMAT=ascii\n\n1 2 3\n";
    std::ofstream(scratch / "c.mtx") << "#?RADIANCE\nNROWS=2\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n1 2 3 4\n";
    std::ofstream(scratch / "f.mtx") << "#?RADIANCE\nNROWS=2\nNCOLS=2\nNCOMP=1\nFORMAT=float\n\n" << std::string(12, '\0');
    std::ofstream(scratch / "d.mtx") << "#?RADIANCE\nNROWS=1\nNCOLS=1\nNCOMP=3\nFORMAT=ascii\n\n1 2 3\n";
    std::ofstream(scratch / "splits.mtx") << "#?RADIANCE\nNROWS=1\nNCOLS=1\nNCOMP=4\nWAVELENGTH_SPLITS= nan 588 480 380\n"
                                              "FORMAT=ascii\n\n1 2 3 4\n";
    std::ofstream(scratch / "narrow.mtx") << "#?RADIANCE\nNROWS=1\nNCOLS=1\nNCOMP=4\nWAVELENGTH_SPLITS= 500 490 480 470\n"
                                              "FORMAT=ascii\n\n1 2 3 4\n";
    std::ofstream(scratch / "x.mtx") << "#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n1 1e999\n";
    expectRefused(scratch, {{"gendaymtx short.wea", "gendaymtx: short.wea:3: .wea header ends before its time_zone line"},
                   {"gendaymtx units.wea", "gendaymtx: units.wea:6: weather_data_file_units must be 1, 2 or 3"},
                   {"gendaymtx record.wea", "gendaymtx: record.wea:8: bad direct value 'eight'"},
                   {"gendaymtx date.wea", "gendaymtx: date.wea:7: impossible date or time"},
                   {"gendaymtx latitude.wea", "gendaymtx: latitude.wea:5: latitude outside -90..90"},
                   {"gendaymtx < /dev/null", "gendaymtx: <stdin>: empty weather tape"},
                   {"gendaymtx -m 0 x.wea", "gendaymtx: -m must be 1 to 32"},
                   {"gendaymtx -oq x.wea", "gendaymtx: bad output format -oq"},
                   {"gendaymtx nothere.wea", "gendaymtx: cannot open weather tape 'nothere.wea'"},
                   {"epw2wea record.wea", "epw2wea: record.wea: this does not seem to be an EPW file"},
                   {"epw2wea", "epw2wea: wrong number of arguments"},
                   {"rmtxop a.mtx", "rmtxop: a.mtx: 3 values for a 2x2x1 matrix"},
                   {"rmtxop c.mtx b.mtx", "rmtxop: cannot multiply a 2x2x1 matrix by a 3x1x1 one"},
                   {"rmtxop c.mtx + b.mtx", "rmtxop: element by element, a 2x2x1 matrix and a 3x1x1 one do not match"},
                   {"rmtxop f.mtx", "rmtxop: f.mtx: truncated: 3 values for a 2x2x1 matrix"},
                   {"rmtxop x.mtx", "rmtxop: x.mtx: value out of range at element 1"},
                   {"rmtxop c.mtx +", "rmtxop: an operator with no matrix after it"},
                   {"rmtxop -c 1 2 d.mtx", "rmtxop: 2 component weights for a matrix of 3 components"},
                   {"rmtxop -c XYZ c.mtx", "rmtxop: symbolic components (-c XYZ) need 3 components or more, not 1"},
                   {"rmtxop -c Y splits.mtx", "rmtxop: 'WAVELENGTH_SPLITS= nan 588 480 380': the spectral range must span 50 nm"},
                   {"rmtxop -c M narrow.mtx", "rmtxop: 'WAVELENGTH_SPLITS= 500 490 480 470': the spectral range must span 50 nm"},
                   {"dctimestep c.mtx b.mtx", "dctimestep: cannot multiply a 2x2x1 matrix by a 3x1x1 one"},
                   {"dctimestep 'c%03d.hdr' b.mtx", "dctimestep: c000.hdr: cannot open"}});
}

// A record without the irradiances the sky needs (EPW's 9999) is an error naming it, not a dark hour.
TEST(DaymtxCli, MissingIrradianceIsAnError) {
    if (!fs::exists(kWeather / "chicago.epw")) GTEST_SKIP() << "no shared weather data";
    fs::path scratch = brume_test::scratchDir("daymtx_missing");
    std::ifstream in(kWeather / "chicago.epw");
    std::ofstream out(scratch / "gap.epw");
    std::string line;
    for (int i = 1; std::getline(in, line) && i <= 20; ++i) {
        if (i == 20) {  // the record of 1 January, 12:00: its direct normal irradiance (field 15) missing
            std::vector<std::string> f;
            std::istringstream fields(line);
            for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
            f[14] = "9999";
            line.clear();
            for (size_t k = 0; k < f.size(); ++k) line += (k ? "," : "") + f[k];
        }
        out << line << "\n";
    }
    out.close();
    Output r = runIn(scratch, "gendaymtx gap.epw");
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(r.out.empty());
    EXPECT_EQ(r.err.rfind("gendaymtx: gap.epw:20: missing required irradiances", 0), 0u) << r.err;
}

// daymetrics on the hand-made year, with the hours of its columns, a schedule and the direct sun; and its errors.
TEST(DaymtxCli, DaymetricsWritesPerSensorAndGridMetrics) {
    fs::path scratch = brume_test::scratchDir("daymetrics");
    writeSensorYear(scratch);
    Output r = runIn(scratch, "daymetrics -hours hours.txt -schedule schedule.txt -direct sun.mtx -ah 2 -g grid.csv ill.mtx");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "sensor,da,cda,udi_lower,udi,udi_upper,sun_hours\n"
                     "0,40.00,56.67,40.00,50.00,10.00,2\n"
                     "1,80.00,80.00,20.00,80.00,0.00,0\n");
    EXPECT_EQ(slurp(scratch / "grid.csv"), "metric,value\nsensors,2\noccupied_hours,10\nsda,50.00\nase,50.00\n");
    expectRefused(scratch, {{"daymetrics ill.mtx", "daymetrics: ill.mtx: 9 columns, not 8760: say which hours they are (-hours)"},
                   {"daymetrics -hours schedule.txt ill.mtx", "daymetrics: ill.mtx: 9 columns for 8760 hours"},
                   {"daymetrics -hours hours.txt -schedule hours.txt ill.mtx", "daymetrics: hours.txt: 9 values, not 8760"},
                   {"daymetrics -hours hours.txt -direct grid.csv ill.mtx", "daymetrics: grid.csv: not a number"},
                   {"daymetrics", "daymetrics: one illuminance matrix"}});
}

// The metrics over the plan of the sensors: one picture a metric, each sensor's cell its value; the sun's hours
// with -direct. Refused: -maps without -pts, sensors that do not match the matrix, a bad or missing sensor file
// (stdout and maps empty).
TEST(DaymtxCli, DaymetricsDrawsEachMetricOverThePlan) {
    fs::path scratch = brume_test::scratchDir("daymetrics_maps");
    std::ofstream(scratch / "grid.pts") << "2 3 0.75 0 0 1\n3 3 0.75 0 0 1\n";
    std::ofstream(scratch / "bad.pts") << "2 3 0.75 0 0 1\n3 3 x 0 0 1\n";
    std::ofstream(scratch / "three.pts") << "2 3 0.75 0 0 1\n3 3 0.75 0 0 1\n4 3 0.75 0 0 1\n";
    writeSensorYear(scratch);
    Output r = runIn(scratch, "daymetrics -hours hours.txt -schedule schedule.txt -direct sun.mtx -pts grid.pts -maps plan ill.mtx");
    ASSERT_EQ(r.status, 0) << r.err;
    brume::Picture da = brume::readPicture((scratch / "plan_da.hdr").string());
    ASSERT_EQ(da.width, 16);
    ASSERT_EQ(da.height, 8);
    // The sensors' DA (40 and 80 %, as DaymetricsWritesPerSensorAndGridMetrics), to RGBE's 8-bit mantissas.
    EXPECT_NEAR(da.at(3, 4)[1], 40, 0.4);
    EXPECT_NEAR(da.at(12, 4)[1], 80, 0.8);
    EXPECT_NE(std::find(da.header.begin(), da.header.end(),
                        "VIEW= -vtl -vp 2.5 3 0.75 -vd 0 0 -1 -vu 0 1 0 -vh 2 -vv 1"), da.header.end());
    brume::Picture sun = brume::readPicture((scratch / "plan_sun_hours.hdr").string());
    EXPECT_NEAR(sun.at(3, 4)[0], 2, 0.02);
    EXPECT_EQ(sun.at(12, 4)[0], 0.f);
    for (const char* metric : {"cda", "udi_lower", "udi", "udi_upper"})
        EXPECT_TRUE(fs::exists(scratch / ("plan_" + std::string(metric) + ".hdr"))) << metric;
    expectRefused(scratch, {{"daymetrics -hours hours.txt -maps refused ill.mtx", "daymetrics: -maps and -pts go together"},
                            {"daymetrics -hours hours.txt -pts three.pts -maps refused ill.mtx",
                             "daymetrics: three.pts: 3 sensors for a matrix of 2"},
                            {"daymetrics -hours hours.txt -pts bad.pts -maps refused ill.mtx", "daymetrics: bad.pts:2: "},
                            {"daymetrics -hours hours.txt -pts none.pts -maps refused ill.mtx", "daymetrics: cannot open 'none.pts'"}});
    EXPECT_FALSE(fs::exists(scratch / "refused_da.hdr"));
}

// -melanopic: melanopic EDI from a spectral year (40 bands over 780-380 nm, WAVELENGTH_SPLITS) and an RGB one.
// CIE S 026 defines EDI so that daylight D65 has the illuminance's value: a sensor under D65 at 0.4 % above and
// below 250 lx of illuminance reaches 250 lx of EDI in one hour of the two (the bands' flat steps move the ratio
// by less than 0.3 %). Radiance's equal-energy white (RGB 1 1 1) has 0.906 of its illuminance in EDI (CIE S
// 026's mel-DER of illuminant E). A single component is refused (illuminance or melanopic? it cannot tell).
TEST(DaymtxCli, DaymetricsCountsHoursOfMelanopicEdi) {
    fs::path scratch = brume_test::scratchDir("daymetrics_melanopic");
    const int bands = 40;
    brume::SpectralSampling sampling;
    sampling.channels = bands;
    const brume::ObserverWeights w = brume::observerWeightsOf(sampling);
    std::vector<double> d65(bands);
    double photopic = 0, melanopic = 0;
    for (int i = 0; i < bands; ++i) {
        auto edges = sampling.band(i);
        d65[i] = brume::illuminantD65().integral(edges[1], edges[0]) / (edges[0] - edges[1]);
        photopic += 179 * w.y[i] * d65[i], melanopic += 179 * w.melanopic[i] * d65[i] * w.melanopicToDaylight;
    }
    EXPECT_NEAR(melanopic / photopic, 1, 0.003);
    std::ofstream spectral(scratch / "spectral.mtx");
    spectral << "#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=40\nWAVELENGTH_SPLITS= 780 588 480 380\nFORMAT=ascii\n\n";
    for (double above : {1.004, 0.996})
        for (int i = 0; i < bands; ++i) spectral << d65[i] * 250 * above / photopic << (i + 1 < bands ? " " : "\n");
    spectral.close();
    const double white = 250 / (179 * 0.906);  // RGB 1 1 1 of 250 lx EDI by CIE S 026's mel-DER
    std::ofstream(scratch / "rgb.mtx") << "#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=3\nFORMAT=ascii\n\n"
                                       << white * 1.004 << " " << white * 1.004 << " " << white * 1.004 << " "
                                       << white * 0.996 << " " << white * 0.996 << " " << white * 0.996 << "\n";
    std::ofstream(scratch / "lux.mtx") << "#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n300 200\n";
    std::ofstream(scratch / "hours.txt") << "8.5\n9.5\n";
    std::ofstream schedule(scratch / "schedule.txt");
    for (int h = 0; h < 8760; ++h) schedule << (h == 8 || h == 9) << "\n";
    schedule.close();
    std::ofstream(scratch / "one.pts") << "1 2 0.75 0 0 1\n";
    const std::string options = "daymetrics -melanopic -hours hours.txt -schedule schedule.txt ";
    for (const char* input : {"spectral.mtx", "rgb.mtx"}) {
        Output r = runIn(scratch, options + "-g grid.csv -pts one.pts -maps plan " + input);
        ASSERT_EQ(r.status, 0) << input << "\n" << r.err;
        EXPECT_EQ(r.out, "sensor,melanopic_da,melanopic_hours\n0,50.00,1\n") << input;
        EXPECT_EQ(slurp(scratch / "grid.csv"), "metric,value\nsensors,1\noccupied_hours,2\nmelanopic_threshold,250\n"
                                               "melanopic_da_mean,50.00\nmelanopic_sda,100.00\n") << input;
        EXPECT_NEAR(brume::readPicture((scratch / "plan_melanopic_da.hdr").string()).at(4, 4)[0], 50, 0.5) << input;
    }
    Output r = runIn(scratch, "daymetrics -hours hours.txt -schedule schedule.txt -t 250 spectral.mtx");
    EXPECT_EQ(r.out.substr(r.out.find('\n') + 1, 8), "0,50.00,") << "the same hours by illuminance";
    expectRefused(scratch, {{"daymetrics -melanopic -hours hours.txt lux.mtx",
                             "daymetrics: lux.mtx: one component may be illuminance or melanopic"},
                            {"daymetrics -melanopic -hours hours.txt -direct lux.mtx rgb.mtx",
                             "daymetrics: -direct and -weather are daylight's, not -melanopic's"}});
}

// EN 17037's daylight hours from a real year: sensors at a steady 400 lx meet the target at 300 lx (level 1)
// and the minimum at 100 and 300 lx (level 2); the daylight hours are Chicago's 4380 brightest.
TEST(DaymtxCli, DaymetricsEn17037FromAWeatherFile) {
    if (!fs::exists(kWeather / "chicago.epw")) GTEST_SKIP() << "no shared weather data";
    fs::path scratch = brume_test::scratchDir("daymetrics_en");
    std::ofstream m(scratch / "ill.mtx");
    m << "#?RADIANCE\nNROWS=2\nNCOLS=8760\nNCOMP=1\nFORMAT=ascii\n\n";
    for (int s = 0; s < 2; ++s)
        for (int h = 0; h < 8760; ++h) m << "400" << (h + 1 < 8760 ? " " : "\n");
    m.close();
    Output r = runIn(scratch, "daymetrics -weather '" + (kWeather / "chicago.epw").string() + "' -g grid.csv ill.mtx");
    ASSERT_EQ(r.status, 0) << r.err;
    std::string grid = slurp(scratch / "grid.csv");
    for (const char* line : {"en17037_target_300,100.00", "en17037_target_500,0.00", "en17037_minimum_300,100.00",
                             "en17037_target_level,1", "en17037_minimum_level,2", "en17037_level,1"})
        EXPECT_NE(grid.find(line), std::string::npos) << line << "\n" << grid;
}
