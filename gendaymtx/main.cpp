// gendaymtx: a sky matrix from a weather tape (.wea or .epw), as Radiance's gendaymtx: one row per sky
// patch (the ground first), one column per record, RGB radiances (see man/gendaymtx.1).
#include <bit>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "sky/sky_matrix.h"
#include "util/error.h"
#include "util/header.h"
#include "util/options.h"

using namespace brume;

namespace {

struct Options {
    SkyMatrixOptions sky;
    bool header = true, verbose = false, average = false, matrix = true;
    char format = 'a';
    std::string sunFile, modifierFile;
};

Rgb rgb(const char* option, const std::vector<std::string>& a) {
    return {toReal(option, a[0]), toReal(option, a[1]), toReal(option, a[2])};
}

OptionTable makeTable(Options& o) {
    OptionTable t;
    auto directOnly = [&o] { o.sky.skyColour = {0, 0, 0}, o.sky.groundReflectance = {0, 0, 0}; };
    auto noMatrix = [&o, directOnly] { o.matrix = false, o.sky.subdivisions = 1, directOnly(); };
    t.add("-g", 3, "ground reflectance r g b (default .2 .2 .2)", [&o](const auto& a) { o.sky.groundReflectance = rgb("-g", a); });
    t.add("-c", 3, "sky colour r g b (default .96 1.004 1.118)", [&o](const auto& a) { o.sky.skyColour = rgb("-c", a); });
    t.add("-m", 1, "Reinhart subdivisions of Tregenza's patches (default 1)", [&o](const auto& a) {
        o.sky.subdivisions = toInt("-m", a[0]);
        if (o.sky.subdivisions < 1 || o.sky.subdivisions > 32) throw Error("-m must be 1 to 32");
    });
    t.add("-r", 1, "rotate the sky (degrees)", [&o](const auto& a) { o.sky.rotation = toReal("-r", a[0]); });
    t.add("-rz", 1, "the same", [&o](const auto& a) { o.sky.rotation = toReal("-rz", a[0]); });
    t.add("-d", 0, "the sun only (no sky, no ground)", [directOnly](const auto&) { directOnly(); });
    t.add("-s", 0, "the sky only (no sun)", [&o](const auto&) { o.sky.sunColour = {0, 0, 0}; });
    t.add("-n", 0, "no matrix (with -D)", [noMatrix](const auto&) { noMatrix(); });
    t.add("-D", 1, "write each record's sun to a file (- : the standard output, no matrix)", [&o, noMatrix](const auto& a) {
        o.sunFile = a[0];
        if (a[0] == "-") noMatrix();
    });
    t.add("-M", 1, "write the suns' modifier names to a file (with -D)", [&o](const auto& a) { o.modifierFile = a[0]; });
    t.add("-u", 0, "only records with the sun up", [&o](const auto&) { o.sky.sunHoursOnly = true; });
    t.add("-A", 0, "one column: the average sky", [&o](const auto&) { o.average = true; });
    t.add("-5", 1, "5-phase: the sun (diameter in degrees) in its one nearest patch at its own solid angle", [&o](const auto& a) {
        double diameter = toReal("-5", a[0]);
        if (!(diameter > 0)) throw Error("-5 needs the solar disc's diameter in degrees");
        double r = kPi / 360 * diameter;
        o.sky.sunPatches = 1, o.sky.sunSolidAngle = kPi * r * r;
    });
    t.add("-i", 1, "minutes a record stands for (sunrise and sunset corrected)", [&o](const auto& a) { o.sky.interval = toReal("-i", a[0]); });
    t.add("-h", 0, "no header", [&o](const auto&) { o.header = false; });
    t.add("-v", 0, "report progress", [&o](const auto&) { o.verbose = true; });
    t.addAttached("-o", "output format: a (ASCII, default), f (float), d (double)", [&o](const std::string& v) {
        if (v != "a" && v != "f" && v != "d") throw Error("bad output format -o" + v);
        o.format = v[0];
    });
    t.addAttached("-O", "0: visible radiance (default), 1: solar radiance", [&o](const std::string& v) {
        if (v != "0" && v != "1") throw Error("bad output type -O" + v);
        o.sky.solarRadiance = v == "1";
    });
    return t;
}

const std::string kUsage =
    "usage: gendaymtx [-v][-h][-A][-d|-s|-n][-u][-D file [-M modfile]][-r deg][-m N][-g r g b][-c r g b][-o{f|d}][-O{0|1}] [tape.wea]\n";

// An output file, opened before the tape is read; closed (and checked) at the end.
std::unique_ptr<std::FILE, int (*)(std::FILE*)> openOutput(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) throw Error("cannot open '" + path + "' for output");
    return {f, std::fclose};
}

std::string header(const std::vector<std::string>& command, const WeatherSite& site, int rows, int cols, int averaged,
                   char format) {
    char latlong[80];
    std::snprintf(latlong, sizeof latlong, "LATLONG= %.8f %.8f\n", site.latitude, site.longitude);
    std::string h = "#?RADIANCE\n" + commandLine(command) + "\n" + latlong + "NROWS=" + std::to_string(rows) + "\nNCOLS=" +
                    std::to_string(cols) + "\n";
    if (averaged) h += "NAVERAGED=" + std::to_string(averaged) + "\n";
    h += "NCOMP=3\n";
    if (format != 'a') h += std::string("BigEndian=") + (std::endian::native == std::endian::big ? "1" : "0") + "\n";
    endHeader(h, format == 'f' ? "float" : format == 'd' ? "double" : "ascii", stdout);
    return h;
}

// Patches are rows, records columns.
void writeMatrix(const std::vector<std::vector<float>>& columns, int patches, char format) {
    for (int p = 0; p < patches; ++p) {
        for (const std::vector<float>& c : columns) {
            const float* v = &c[3 * size_t(p)];
            if (format == 'a') std::printf("%.3g %.3g %.3g\n", v[0], v[1], v[2]);
            else if (format == 'f') std::fwrite(v, sizeof(float), 3, stdout);
            else {
                double d[3] = {v[0], v[1], v[2]};
                std::fwrite(d, sizeof(double), 3, stdout);
            }
        }
        if (format == 'a' && columns.size() > 1) std::fputc('\n', stdout);
    }
}

int run(int argc, char** argv) {
    Options o;
    OptionTable table = makeTable(o);
    std::vector<std::string> operands = operandsAfterOptions(table, argc, argv, kUsage);
    if (operands.size() > 1) throw UsageError("one weather tape at most", kUsage + table.usage());
    std::string name = operands.empty() ? "<stdin>" : operands[0];
    std::ifstream file;
    if (!operands.empty()) {
        file.open(name);
        if (!file) throw Error("cannot open weather tape '" + name + "'");
    }
    WeatherTape tape(operands.empty() ? std::cin : static_cast<std::istream&>(file), name);
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> suns{nullptr, std::fclose}, modifiers{nullptr, std::fclose};
    std::FILE* sunOut = nullptr;
    if (!o.sunFile.empty()) {
        if (o.sunFile != "-") suns = openOutput(o.sunFile);
        sunOut = suns ? suns.get() : stdout;
        std::fprintf(sunOut, "#\n# Sun positions generated by:\n#\t%s\n#\n", commandLine({argv, argv + argc}).c_str());
    }
    if (!o.modifierFile.empty()) {
        modifiers = openOutput(o.modifierFile);
        if (!sunOut) warn("-M output will be empty without -D");
    }
    if (o.verbose) std::fprintf(stderr, "%s: location '%s, %s'\n", programName().c_str(), tape.site().city.c_str(), tape.site().country.c_str());
    SkySteps steps(tape.site(), tape.units(), o.sky);
    std::vector<std::vector<float>> columns;
    std::vector<float> sum;  // in single precision, as gendaymtx sums
    int count = 0, lastMonth = 0;
    while (std::optional<WeatherRecord> record = tape.next()) {
        std::optional<SkyStep> s = steps.step(*record);
        if (!s) continue;
        ++count;
        if (sunOut && s->sunInSky) {
            std::fputs(sunDescription(*s, o.sky.sunColour, !s->dark).c_str(), sunOut);
            if (modifiers) std::fprintf(modifiers.get(), "solar%d\n", s->minuteOfYear);
        }
        if (!o.matrix) continue;
        if (o.average) {
            sum.resize(s->patches.size());
            for (size_t i = 0; i < sum.size(); ++i) sum[i] += s->patches[i];
        } else columns.push_back(std::move(s->patches));
        if (o.verbose && record->month != lastMonth)
            std::fprintf(stderr, "%s: stepping through month %d...\n", programName().c_str(), lastMonth = record->month);
    }
    if (count == 0) throw Error(name + ": no valid time steps");
    if (!o.matrix) return 0;
    if (o.average) {
        columns.emplace_back(sum.size());
        for (size_t i = 0; i < sum.size(); ++i) columns[0][i] = float(sum[i] * (1.0 / count));
    }
    if (o.header)
        std::fputs(header({argv, argv + argc}, tape.site(), steps.patches().size(), int(columns.size()), o.average ? count : 0, o.format).c_str(), stdout);
    writeMatrix(columns, steps.patches().size(), o.format);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    setProgramName(argv[0]);
    return runReportingErrors([&] { return run(argc, argv); });
}
