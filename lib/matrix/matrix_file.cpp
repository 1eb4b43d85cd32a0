#include "matrix/matrix_file.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "io/picture.h"
#include "matrix/bsdf_matrix.h"
#include "util/error.h"
#include "util/header.h"

namespace brume {

namespace {

constexpr long kMaxElements = 1L << 31;  // 8 GB of floats: refused before allocating
constexpr int kMaxComponents = 1000;     // spectral bands, more than any spectrum has

std::string readAll(std::FILE* f) {
    std::string bytes;
    char buffer[1 << 16];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) bytes.append(buffer, n);
    return bytes;
}

std::string inputBytes(const std::string& spec) {
    if (spec == "-") return readAll(stdin);  // in blocks: std::cin, synchronised with stdio, reads a byte at a time
    if (!spec.empty() && spec[0] == '!') {
        std::FILE* pipe = popen(spec.c_str() + 1, "r");
        if (!pipe) throw Error("cannot run '" + spec.substr(1) + "'");
        std::string bytes = readAll(pipe);
        if (pclose(pipe) != 0) throw Error("command '" + spec.substr(1) + "' failed");
        return bytes;
    }
    std::FILE* file = std::fopen(spec.c_str(), "rb");
    if (!file) throw Error("cannot open matrix file '" + spec + "'");
    std::string bytes = readAll(file);
    std::fclose(file);
    return bytes;
}

// Values that overflow single precision (huge inputs, an exposure's scale, products) are refused, not written.
void requireFinite(const Matrix& m, const std::string& what) {
    for (float v : m.values)
        if (!std::isfinite(v)) throw Error(what + ": a value overflows single precision");
}

struct Header {
    int rows = 0, cols = 0, comps = 0;
    std::optional<MatrixFormat> format;
    bool swap = false;
    double exposure = 1;
    std::vector<std::string> info;
    size_t end = 0;  // where the data start
};

int headerCount(const std::string& line, size_t from, const std::string& name) {
    char* end;
    long v = std::strtol(line.c_str() + from, &end, 10);
    if (end == line.c_str() + from || v <= 0 || v > (1 << 30)) throw Error(name + ": bad header line '" + shownBytes(line, 60) + "'");
    return int(v);
}

Header parseHeader(const std::string& bytes, const std::string& name) {
    Header h;
    if (bytes.compare(0, 2, "#?") != 0) return h;
    size_t at = 0;
    for (;;) {
        size_t eol = bytes.find('\n', at);
        if (eol == std::string::npos) throw Error(name + ": the header does not end (no empty line)");
        std::string line = bytes.substr(at, eol - at);
        at = eol + 1;
        if (line.empty()) break;
        if (line.compare(0, 2, "#?") == 0) continue;
        if (line.compare(0, 6, "NROWS=") == 0) h.rows = headerCount(line, 6, name);
        else if (line.compare(0, 6, "NCOLS=") == 0) h.cols = headerCount(line, 6, name);
        else if (line.compare(0, 6, "NCOMP=") == 0) {
            h.comps = headerCount(line, 6, name);
            if (h.comps > kMaxComponents) throw Error(name + ": " + std::to_string(h.comps) + " components (at most " + std::to_string(kMaxComponents) + ")");
        }
        else if (line.compare(0, 10, "BigEndian=") == 0) h.swap = (std::atoi(line.c_str() + 10) != 0) != (std::endian::native == std::endian::big);
        else if (line.compare(0, 9, "EXPOSURE=") == 0) h.exposure *= std::atof(line.c_str() + 9);
        else if (line.compare(0, 7, "FORMAT=") == 0) {
            std::string f = line.substr(7);
            while (!f.empty() && (f.back() == ' ' || f.back() == '\r')) f.pop_back();
            if (f == "ascii") h.format = MatrixFormat::Ascii;
            else if (f == "float") h.format = MatrixFormat::Float;
            else if (f == "double") h.format = MatrixFormat::Double;
            else if (f == "32-bit_rle_rgbe" || f == "32-bit_rle_xyze") h.format = MatrixFormat::Rgbe;
            else throw Error(name + ": matrix format '" + shownBytes(f, 40) + "' is not ascii, float, double or RGBE");
        } else h.info.push_back(line);
    }
    h.end = at;
    return h;
}

// The rows from the number of elements when the header (or the caller) gave only the columns.
void completeSize(Header& h, size_t elements, const std::string& name) {
    if (elements > size_t(kMaxElements)) throw Error(name + ": matrix too large");
    if (elements == 0) throw Error(name + ": no values");
    if (h.cols <= 0 && h.rows > 0 && elements % h.rows == 0) h.cols = int(elements / h.rows);
    if (h.cols <= 0) h.cols = int(std::min<size_t>(elements, size_t(1) << 30)), h.rows = 1;
    if (h.rows <= 0) {
        if (elements % h.cols) throw Error(name + ": " + std::to_string(elements) + " elements do not fill rows of " + std::to_string(h.cols));
        h.rows = int(elements / h.cols);
    }
    if (double(h.rows) * h.cols * h.comps > double(kMaxElements)) throw Error(name + ": matrix too large");
}

Matrix asciiValues(const std::string& bytes, Header& h, const std::string& name) {
    std::vector<float> values;
    const char* p = bytes.c_str() + h.end;
    const char* last = bytes.c_str() + bytes.size();
    for (;;) {
        // from_chars (strtod's value, exactly rounded, at a fraction of its cost); strtod for what it alone
        // reads (a '+' sign, hexadecimal, inf, nan: refused below).
        while (p < last && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) ++p;
        double v;
        auto [stop, error] = std::from_chars(p, last, v);
        const char* end = stop;
        if (error != std::errc() || (end < last && (*end == 'x' || *end == 'X'))) {
            char* e;
            v = std::strtod(p, &e);
            end = e;
        }
        if (end == p) break;
        if (!std::isfinite(v) || std::abs(v) > 3.4e38) throw Error(name + ": value out of range at element " + std::to_string(values.size() / h.comps));
        values.push_back(float(v));
        p = end;
    }
    while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') ++p;
    if (*p) throw Error(name + ": not a number: '" + shownBytes(p, 20) + "'");
    if (values.size() % h.comps) throw Error(name + ": " + std::to_string(values.size()) + " values are not whole elements of " + std::to_string(h.comps));
    completeSize(h, values.size() / h.comps, name);
    Matrix m(h.rows, h.cols, h.comps);
    if (values.size() != m.values.size())
        throw Error(name + ": " + std::to_string(values.size()) + " values for a " + std::to_string(h.rows) + "x" + std::to_string(h.cols) +
                    "x" + std::to_string(h.comps) + " matrix");
    m.values = std::move(values);
    return m;
}

template <typename T>
Matrix binaryValues(const std::string& bytes, Header& h, const std::string& name) {
    size_t available = (bytes.size() - h.end) / sizeof(T);
    completeSize(h, available / h.comps, name);
    if (size_t(h.rows) * h.cols * h.comps > available)  // before allocating what the header claims
        throw Error(name + ": truncated: " + std::to_string(available) + " values for a " + std::to_string(h.rows) + "x" + std::to_string(h.cols) +
                    "x" + std::to_string(h.comps) + " matrix");
    Matrix m(h.rows, h.cols, h.comps);
    const char* p = bytes.data() + h.end;
    for (size_t i = 0; i < m.values.size(); ++i) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, p + i * sizeof(T), sizeof(T));
        if (h.swap) std::reverse(b, b + sizeof(T));
        T v;
        std::memcpy(&v, b, sizeof(T));
        if (!std::isfinite(double(v)) || std::abs(double(v)) > 3.4e38) throw Error(name + ": value out of range at element " + std::to_string(i / h.comps));
        m.values[i] = float(v);
    }
    return m;
}

Matrix pictureValues(const std::string& bytes, const std::string& name) {
    std::istringstream in(bytes);
    Picture p = readRadiancePicture(in, name);
    Matrix m(p.height, p.width, 3);
    // Undo the exposure of pictures that were scaled after they were made (pcomb -o's rule).
    double exposure = p.exposure > 0 ? p.exposure : 1;
    for (size_t i = 0; i < m.values.size(); ++i) m.values[i] = float(p.pixels[i] / exposure);
    for (const std::string& line : p.header)
        if (line.compare(0, 9, "EXPOSURE=") != 0) m.info.push_back(line);
    requireFinite(m, name);
    return m;
}

// printf's "%.Ne" digits (both round exactly), without printf's cost: a year of sensors is millions of them.
void appendScientific(std::string& line, double v, int precision) {
    char buffer[32];
    auto end = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::scientific, precision).ptr;
    line.append(buffer, end);
}

void writeAscii(std::FILE* out, const Matrix& m, AsciiLayout layout) {
    std::string line;
    for (int r = 0; r < m.rows; ++r) {
        line.clear();
        for (int c = 0; c < m.cols; ++c) {
            const float* e = m.at(r, c);
            for (int k = 0; k < m.comps; ++k) {
                if (layout == AsciiLayout::Rmtxop || k) line += ' ';
                appendScientific(line, e[k], layout == AsciiLayout::Rmtxop ? 7 : 6);
            }
            if (layout == AsciiLayout::Rmtxop || c + 1 < m.cols) line += '\t';
        }
        line += '\n';
        std::fwrite(line.data(), 1, line.size(), out);
    }
}

}  // namespace

std::string formatName(MatrixFormat f) {
    switch (f) {
        case MatrixFormat::Float: return "float";
        case MatrixFormat::Double: return "double";
        case MatrixFormat::Rgbe: return "32-bit_rle_rgbe";
        default: return "ascii";
    }
}

Matrix parseMatrix(const std::string& bytes, const std::string& name, const MatrixShape& shape, MatrixFormat* stored) {
    Header h = parseHeader(bytes, name);
    MatrixFormat format = h.format.value_or(shape.format.value_or(MatrixFormat::Ascii));
    if (stored) *stored = format;
    if (format == MatrixFormat::Rgbe) return pictureValues(bytes, name);
    if (h.comps <= 0) h.comps = shape.comps;  // 3 unless told: Radiance's default without NCOMP
    if (h.end == 0) h.cols = shape.cols;
    Matrix m = format == MatrixFormat::Ascii  ? asciiValues(bytes, h, name)
               : format == MatrixFormat::Float ? binaryValues<float>(bytes, h, name)
                                               : binaryValues<double>(bytes, h, name);
    if (h.exposure != 1 && h.exposure > 0) scale(m, {1 / h.exposure});
    requireFinite(m, name);
    m.info = std::move(h.info);
    return m;
}

Matrix readMatrix(const std::string& spec, const MatrixShape& shape, MatrixFormat* stored) {
    if (isBsdfFile(spec)) {
        if (stored) *stored = MatrixFormat::Ascii;
        return transmissionMatrix(spec);
    }
    return parseMatrix(inputBytes(spec), spec == "-" ? "<stdin>" : spec, shape, stored);
}

void writePicture(std::FILE* out, const Matrix& m, const std::vector<std::string>& lines, PictureHeader header) {
    requireFinite(m, "the result");
    if (m.comps != 3) throw Error("a picture needs 3 components, not " + std::to_string(m.comps));
    Picture p;
    p.width = m.cols, p.height = m.rows;
    p.pixels = m.values;
    p.header = lines;
    std::ostringstream bytes;
    writeRadiancePicture(bytes, p, header == PictureHeader::LaterFrame);
    std::string s = bytes.str();
    if (header == PictureHeader::None) s = s.substr(s.find("\n\n") + 2);
    std::fwrite(s.data(), 1, s.size(), out);
}

void writeMatrix(std::FILE* out, const Matrix& m, MatrixFormat format, AsciiLayout layout,
                 const std::vector<std::string>& lines, bool header) {
    if (format == MatrixFormat::Rgbe) {
        std::vector<std::string> all = lines;
        all.insert(all.end(), m.info.begin(), m.info.end());
        writePicture(out, m, header ? all : std::vector<std::string>{}, header ? PictureHeader::Whole : PictureHeader::None);
        return;
    }
    requireFinite(m, "the result");
    if (header) {
        std::string h = "#?RADIANCE\n";
        for (const std::string& line : lines) h += line + "\n";
        for (const std::string& line : m.info) h += line + "\n";
        h += "NROWS=" + std::to_string(m.rows) + "\nNCOLS=" + std::to_string(m.cols) + "\nNCOMP=" + std::to_string(m.comps) + "\n";
        if (format != MatrixFormat::Ascii) h += std::string("BigEndian=") + (std::endian::native == std::endian::big ? "1" : "0") + "\n";
        endHeader(h, formatName(format), out);
        std::fputs(h.c_str(), out);
    }
    if (format == MatrixFormat::Ascii) return writeAscii(out, m, layout);
    if (format == MatrixFormat::Float) {
        std::fwrite(m.values.data(), sizeof(float), m.values.size(), out);
        return;
    }
    std::vector<double> d(m.values.begin(), m.values.end());
    std::fwrite(d.data(), sizeof(double), d.size(), out);
}

}  // namespace brume
