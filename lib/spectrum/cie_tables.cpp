#include "spectrum/cie_tables.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

#include "spectrum/embedded_cie.h"
#include "util/error.h"

namespace brume {

double TabulatedSpectrum::last() const { return first + step * (values.empty() ? 0 : double(values.size() - 1)); }

double TabulatedSpectrum::at(double nm) const {
    if (values.empty() || !(nm >= first && nm <= last())) return 0;
    if (values.size() == 1) return values[0];
    double t = (nm - first) / step;
    size_t i = std::min(size_t(t), values.size() - 2);
    double f = t - double(i);
    return values[i] * (1 - f) + values[i + 1] * f;
}

double TabulatedSpectrum::integral(double lo, double hi) const {
    if (hi < lo) return -integral(hi, lo);
    lo = std::max(lo, first), hi = std::min(hi, last());
    if (values.size() < 2 || !(hi > lo)) return 0;
    // Each step's share is exact by the trapezoid rule, the function being linear there.
    size_t begin = size_t((lo - first) / step), end = std::min(size_t(std::ceil((hi - first) / step)), values.size() - 1);
    double sum = 0;
    for (size_t i = begin; i < end; ++i) {
        double a = std::max(lo, first + step * double(i)), b = std::min(hi, first + step * double(i + 1));
        if (b > a) sum += (b - a) * (at(a) + at(b)) / 2;
    }
    return sum;
}

namespace {

// The columns of one of the CIE's CSV files: wavelength first, at equal steps. Empty and non-numeric
// cells (the CIE writes "NaN" where a function is not defined) are 0.
std::vector<TabulatedSpectrum> readCsv(std::string_view name) {
    const EmbeddedFile* file = findEmbedded(embeddedCieTables(), name);
    if (!file) throw Error("CIE table \"" + std::string(name) + "\" is not in the library");
    std::vector<double> wavelengths;
    std::vector<TabulatedSpectrum> columns;
    std::string_view text = file->text;
    while (!text.empty()) {
        size_t end = text.find_first_of("\r\n");
        std::string_view line = text.substr(0, end);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
        if (line.empty()) continue;
        for (size_t column = 0;; ++column) {
            size_t comma = line.find(',');
            std::string cell(line.substr(0, comma));
            char* stop;
            double v = std::strtod(cell.c_str(), &stop);
            if (stop == cell.c_str() || !std::isfinite(v)) v = 0;
            if (column == 0) wavelengths.push_back(v);
            else {
                if (columns.size() < column) columns.resize(column);
                columns[column - 1].values.resize(wavelengths.size() - 1);  // cells missing above are 0
                columns[column - 1].values.push_back(v);
            }
            if (comma == std::string_view::npos) break;
            line.remove_prefix(comma + 1);
        }
    }
    if (wavelengths.size() < 2) throw Error("CIE table \"" + std::string(name) + "\" has too few rows");
    double step = wavelengths[1] - wavelengths[0];
    for (size_t i = 1; i < wavelengths.size(); ++i)
        if (std::abs(wavelengths[i] - wavelengths[0] - step * double(i)) > 1e-9)
            throw Error("CIE table \"" + std::string(name) + "\" is not at equal steps");
    for (TabulatedSpectrum& c : columns) {
        c.first = wavelengths[0], c.step = step;
        c.values.resize(wavelengths.size());
    }
    return columns;
}

struct CieTables {
    std::vector<TabulatedSpectrum> xyz = readCsv("CIE_xyz_1931_2deg.csv");
    // S-cone, M-cone, L-cone, rhodopic, melanopic (CIE S 026).
    std::vector<TabulatedSpectrum> alphaOpic = readCsv("CIE_a-opic_action_spectra.csv");
    TabulatedSpectrum scotopic = readCsv("CIE_sle_scotopic.csv").at(0);
    TabulatedSpectrum a = readCsv("CIE_std_illum_A_1nm.csv").at(0);
    TabulatedSpectrum d65 = readCsv("CIE_std_illum_D65.csv").at(0);
};

// A function-local static: built by the first caller, the others wait for it.
const CieTables& tables() {
    static const CieTables t;
    return t;
}

}  // namespace

const TabulatedSpectrum& cieX() { return tables().xyz.at(0); }
const TabulatedSpectrum& cieY() { return tables().xyz.at(1); }
const TabulatedSpectrum& cieZ() { return tables().xyz.at(2); }
const TabulatedSpectrum& scotopicEfficiency() { return tables().scotopic; }
const TabulatedSpectrum& melanopicEfficiency() { return tables().alphaOpic.at(4); }
const TabulatedSpectrum& illuminantA() { return tables().a; }
const TabulatedSpectrum& illuminantD65() { return tables().d65; }

}  // namespace brume
