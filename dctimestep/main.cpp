// dctimestep: daylight coefficients times sky vectors or matrices (DC × sky, or V × T × D × sky; DC or V as a
// picture per bin, summed into pictures), as Radiance's dctimestep (see man/dctimestep.1).
#include <cstdio>
#include <functional>
#include <memory>

#include "matrix/component_pictures.h"
#include "matrix/matrix_file.h"
#include "util/error.h"
#include "util/header.h"
#include "util/options.h"

using namespace brume;

namespace {

const std::string kUsage =
    "usage: dctimestep [-n nsteps][-o ospec][-x xr][-y yr][-i{f|d|h}][-o{f|d|c}] DCspec [skyf]\n"
    "   or: dctimestep [-n nsteps][-o ospec][-x xr][-y yr][-i{f|d|h}][-o{f|d|c}] Vspec Tbsdf Dmat.dat [skyf]\n";

struct Options {
    int steps = 0;
    bool header = true;
    std::string outputSpec;
    int xres = 0, yres = 0;
    std::optional<MatrixFormat> skyFormat;
    MatrixFormat format = MatrixFormat::Ascii;
};

OptionTable makeTable(Options& o) {
    OptionTable t;
    t.add("-n", 1, "time steps of a sky without a header", [&o](const auto& a) { o.steps = toInt("-n", a[0]); });
    t.add("-h", 0, "no header", [&o](const auto&) { o.header = false; });
    t.add("-o", 1, "output file, or files with %d (the time step)", [&o](const auto& a) { o.outputSpec = a[0]; });
    for (const char* f : {"-oa", "-of", "-od", "-oc"})
        t.add(f, 0, "output format: ASCII, float, double, RGBE picture", [&o, f](const auto&) {
            o.format = f[2] == 'f' ? MatrixFormat::Float : f[2] == 'd' ? MatrixFormat::Double : f[2] == 'c' ? MatrixFormat::Rgbe : MatrixFormat::Ascii;
        });
    for (const char* f : {"-ia", "-if", "-id", "-ih"})
        t.add(f, 0, "sky format without a header: ASCII, float, double (h: the header says)", [&o, f](const auto&) {
            o.skyFormat = f[2] == 'f' ? std::optional(MatrixFormat::Float) : f[2] == 'd' ? std::optional(MatrixFormat::Double)
                          : f[2] == 'a' ? std::optional(MatrixFormat::Ascii) : std::nullopt;
        });
    t.add("-x", 1, "picture width (-oc)", [&o](const auto& a) { o.xres = toInt("-x", a[0]); });
    t.add("-y", 1, "picture height (-oc)", [&o](const auto& a) { o.yres = toInt("-y", a[0]); });
    t.add("-N", 1, "processes (no effect: one process multiplies in a moment)", [](const auto&) {});
    t.add("-m", 1, "memory in GB (no effect)", [](const auto&) {});
    return t;
}

// A column as a picture: -x and -y, or one of them and the column's length.
Matrix asPicture(const Matrix& column, int xres, int yres) {
    int n = column.rows * column.cols;
    if (xres <= 0 && yres > 0 && n % yres == 0) xres = n / yres;
    if (yres <= 0 && xres > 0 && n % xres == 0) yres = n / xres;
    if (xres <= 0 || yres <= 0 || xres * yres != n)
        throw Error("a picture of " + std::to_string(n) + " values needs -x and -y that multiply to it");
    Matrix p(yres, xres, column.comps);
    p.values = column.values;
    return p;
}

Matrix columnOf(const Matrix& m, int c) {
    Matrix out(m.rows, 1, m.comps);
    for (int r = 0; r < m.rows; ++r) std::copy_n(m.at(r, c), m.comps, out.at(r, 0));
    return out;
}

void write(std::FILE* out, Matrix m, const Options& o, std::vector<std::string> lines) {
    if (o.format == MatrixFormat::Rgbe && (o.xres > 0 || o.yres > 0)) m = asPicture(m, o.xres, o.yres);
    m.info.clear();  // dctimestep's header holds its own command and the time, not its inputs'
    writeMatrix(out, m, o.format, AsciiLayout::Dctimestep, lines, o.header);
}

// Pictures of several time steps one after another in one stream, as Radiance's dctimestep writes them: the header
// once, then each frame's FRAME= line, FORMAT= and pixels.
void writeFrames(std::FILE* out, int steps, const std::function<Matrix(int)>& frame, const std::vector<std::string>& lines,
                 bool header) {
    for (int c = 0; c < steps; ++c) {
        bool first = c == 0 && header;
        std::vector<std::string> named = first ? lines : std::vector<std::string>{};
        named.push_back("FRAME=" + std::to_string(c));
        writePicture(out, frame(c), named, first ? PictureHeader::Whole : PictureHeader::LaterFrame);
    }
}

int run(int argc, char** argv) {
    Options o;
    OptionTable table = makeTable(o);
    std::vector<std::string> specs = operandsAfterOptions(table, argc, argv, kUsage);
    if (specs.empty() || specs.size() > 4) throw UsageError("one to four matrices", kUsage + table.usage());
    // DC [sky] or V T D [sky]: the sky is last when there are two or four, else the standard input.
    bool skyGiven = specs.size() == 2 || specs.size() == 4;
    std::vector<std::string> factors(specs.begin(), skyGiven ? specs.end() - 1 : specs.end());
    if (factors.size() != 1 && factors.size() != 3) throw UsageError("one or three matrices before the sky", kUsage + table.usage());
    for (size_t i = 1; i < specs.size(); ++i)
        if (namesComponentPictures(specs[i])) throw Error(specs[i] + ": only the first matrix may be pictures by bin");
    // A sky without a header is a vector unless -n says how many steps.
    MatrixShape shape{o.skyFormat, o.steps > 0 ? o.steps : 1, 3};
    // Multiplied from the sky back, as Radiance's: T (D sky), then the first matrix (or its pictures) times that.
    Matrix weights = readMatrix(skyGiven ? specs.back() : "-", shape);
    for (size_t i = factors.size() - 1; i >= 1; --i) weights = multiply(readMatrix(factors[i]), weights);
    const bool pictures = namesComponentPictures(factors[0]);
    if (pictures) o.format = MatrixFormat::Rgbe;  // as Radiance's, which says it changes the output to -oc
    Matrix result = pictures ? Matrix() : multiply(readMatrix(factors[0]), weights);
    auto frame = [&](int step) { return pictures ? sumComponentPictures(factors[0], weights, step) : columnOf(result, step); };
    std::vector<std::string> lines = {commandLine({argv, argv + argc})};
    std::string dates = softwareAndDates();
    for (size_t at = 0, eol; (eol = dates.find('\n', at)) != std::string::npos; at = eol + 1) lines.push_back(dates.substr(at, eol - at));
    if (o.outputSpec.find('%') != std::string::npos) {
        for (int c = 0; c < weights.cols; ++c) {
            char path[4096];
            std::snprintf(path, sizeof path, o.outputSpec.c_str(), c);
            std::unique_ptr<std::FILE, int (*)(std::FILE*)> f{std::fopen(path, "wb"), std::fclose};
            if (!f) throw Error("cannot open '" + std::string(path) + "' for output");
            std::vector<std::string> named = lines;
            named.push_back("FRAME=" + std::to_string(c));
            write(f.get(), frame(c), o, named);
        }
        return 0;
    }
    if (weights.cols > 1 && !pictures && o.format == MatrixFormat::Rgbe && (o.xres > 0 || o.yres > 0))
        throw Error("-oc with -x/-y makes one picture per time step: give -o with %d");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f{nullptr, std::fclose};
    if (!o.outputSpec.empty()) {
        f.reset(std::fopen(o.outputSpec.c_str(), "wb"));
        if (!f) throw Error("cannot open '" + o.outputSpec + "' for output");
    }
    std::FILE* out = f ? f.get() : stdout;
    if (pictures && weights.cols > 1) {
        writeFrames(out, weights.cols, frame, lines, o.header);
        return 0;
    }
    write(out, pictures ? frame(0) : std::move(result), o, lines);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    setProgramName(argv[0]);
    return runReportingErrors([&] { return run(argc, argv); });
}
