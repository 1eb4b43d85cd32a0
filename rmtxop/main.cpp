// rmtxop: concatenate (multiply), add, multiply or divide element by element, transpose, transform and scale
// matrices, left to right, as Radiance's rmtxop (see man/rmtxop.1).
#include <array>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "matrix/matrix_file.h"
#include "matrix/symbolic_components.h"
#include "util/error.h"
#include "util/header.h"

using namespace brume;

namespace {

const char* const kUsage =
    "usage: rmtxop [-v][-f[adfc]][-C ce ..|RGB..][-t][-c ce ..|RGB..][-s sf ..] m1 [.+*/] .. > mres\n";

// What -t, -c and -s ask of one matrix (or of the result, after the last).
struct Changes {
    bool transpose = false;
    std::vector<double> weights;
    std::optional<std::string> symbols;
    std::vector<double> factors;
    bool any() const { return transpose || !weights.empty() || symbols || !factors.empty(); }
};

bool isNumber(const std::string& w) {
    char* end;
    std::strtod(w.c_str(), &end);
    return !w.empty() && *end == '\0';
}

Matrix applied(Matrix m, const Changes& c, const Changes& defaults) {
    if (c.transpose) m = transposed(m);
    const Changes& t = c.weights.empty() && !c.symbols ? defaults : c;
    if (t.symbols) m = transformed(m, symbolWeights(*t.symbols, m));
    else if (!t.weights.empty()) m = transformed(m, t.weights);
    if (!c.factors.empty()) scale(m, c.factors);
    return m;
}

// The lowest precision among the inputs, Radiance's rule: RGBE, then float, then ASCII, then double.
int rank(MatrixFormat f) {
    switch (f) {
        case MatrixFormat::Rgbe: return 0;
        case MatrixFormat::Float: return 1;
        case MatrixFormat::Ascii: return 2;
        default: return 3;
    }
}

int run(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    std::optional<MatrixFormat> output;
    bool verbose = false;
    Changes defaults, pending;
    std::optional<Matrix> result;
    char op = 0;  // the operator read since the last matrix: . + * /
    MatrixFormat lowest = MatrixFormat::Double;
    auto numbers = [&](size_t& i, std::vector<double>& into, const std::string& option) {
        while (i + 1 < args.size() && isNumber(args[i + 1])) into.push_back(std::atof(args[++i].c_str()));
        if (into.empty()) throw UsageError("missing values for " + option, kUsage);
    };
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "-v") verbose = true;
        else if (a == "-fa") output = MatrixFormat::Ascii;
        else if (a == "-ff") output = MatrixFormat::Float;
        else if (a == "-fd") output = MatrixFormat::Double;
        else if (a == "-fc") output = MatrixFormat::Rgbe;
        else if (a == "-t") pending.transpose = !pending.transpose;
        else if (a == "-c" || a == "-C") {
            Changes& c = a == "-c" ? pending : defaults;
            c.weights.clear(), c.symbols.reset();
            if (i + 1 < args.size() && !isNumber(args[i + 1]) && args[i + 1][0] != '-') c.symbols = args[++i];
            else numbers(i, c.weights, a);
        } else if (a == "-s") numbers(i, pending.factors, a);
        else if (a == "-rf" || a == "-rb") throw Error("BSDF files (" + a + ") are not read by Brume's rmtxop yet");
        else if (a == "." || a == "+" || a == "*" || a == "/") {
            if (!result || op) throw UsageError("operator '" + a + "' without a matrix before it", kUsage);
            op = a[0];
        } else if (a.size() > 1 && a[0] == '-' && !isNumber(a)) throw UsageError("unknown option " + a, kUsage);
        else {
            MatrixFormat stored;
            Matrix m = readMatrix(a, {}, &stored);
            if (rank(stored) < rank(lowest)) lowest = stored;
            Matrix next = applied(std::move(m), pending, defaults);
            pending = {};
            if (!result) result = std::move(next);
            else if (op && op != '.') {
                if (verbose) std::fprintf(stderr, "%s: element-wise '%c' with '%s'\n", programName().c_str(), op, a.c_str());
                result = elementwise(*result, next, op == '+' ? ElementOp::Add : op == '*' ? ElementOp::Multiply : ElementOp::Divide);
            } else {
                if (verbose) std::fprintf(stderr, "%s: multiplying by '%s'\n", programName().c_str(), a.c_str());
                result = multiply(*result, next);
            }
            op = 0;
        }
    }
    if (!result) throw UsageError("no matrix", kUsage);
    if (op) throw UsageError("an operator with no matrix after it", kUsage);
    if (pending.any()) result = applied(std::move(*result), pending, Changes{});
    MatrixFormat format = output.value_or(lowest);
    if (format == MatrixFormat::Rgbe && result->comps != 3) format = MatrixFormat::Float;
    writeMatrix(stdout, *result, format, AsciiLayout::Rmtxop, {commandLine({argv, argv + argc})});
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    setProgramName(argv[0]);
    return runReportingErrors([&] { return run(argc, argv); });
}
