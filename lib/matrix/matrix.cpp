#include "matrix/matrix.h"

#include <algorithm>
#include <string>

#include "util/error.h"

namespace brume {

namespace {

std::string size(const Matrix& m) {
    return std::to_string(m.rows) + "x" + std::to_string(m.cols) + "x" + std::to_string(m.comps);
}

}  // namespace

Matrix multiply(const Matrix& a, const Matrix& b) {
    if (a.cols != b.rows || a.comps != b.comps)
        throw Error("cannot multiply a " + size(a) + " matrix by a " + size(b) + " one");
    Matrix out(a.rows, b.cols, a.comps);
    const int comps = a.comps, n = b.cols * comps;
    std::vector<double> row(n);
    for (int i = 0; i < a.rows; ++i) {
        std::fill(row.begin(), row.end(), 0.0);
        for (int k = 0; k < a.cols; ++k) {
            const float* aik = a.at(i, k);
            if (std::all_of(aik, aik + comps, [](float x) { return x == 0; })) continue;  // sky patches no sensor sees
            const float* bk = b.at(k, 0);
            if (comps == 3) {  // RGB, nearly always: unrolled, the compiler's vector code (sums in the same order)
                const double a0 = aik[0], a1 = aik[1], a2 = aik[2];
                double* r = row.data();
                for (int j = 0; j < b.cols; ++j, r += 3, bk += 3) {
                    r[0] += a0 * bk[0];
                    r[1] += a1 * bk[1];
                    r[2] += a2 * bk[2];
                }
                continue;
            }
            for (int j = 0; j < b.cols; ++j)
                for (int c = 0; c < comps; ++c) row[j * comps + c] += double(aik[c]) * bk[j * comps + c];
        }
        float* o = out.at(i, 0);
        for (int j = 0; j < n; ++j) o[j] = float(row[j]);
    }
    out.info = a.info;
    return out;
}

Matrix transposed(const Matrix& m) {
    Matrix out(m.cols, m.rows, m.comps);
    for (int r = 0; r < m.rows; ++r)
        for (int c = 0; c < m.cols; ++c) std::copy_n(m.at(r, c), m.comps, out.at(c, r));
    out.info = m.info;
    out.note("Transposed rows and columns");
    return out;
}

Matrix transformed(const Matrix& m, const std::vector<double>& weights) {
    if (weights.empty() || weights.size() % m.comps)
        throw Error(std::to_string(weights.size()) + " component weights for a matrix of " + std::to_string(m.comps) +
                    " components (a multiple of it is needed)");
    int comps = int(weights.size()) / m.comps;
    Matrix out(m.rows, m.cols, comps);
    for (size_t e = 0; e < size_t(m.rows) * m.cols; ++e)
        for (int o = 0; o < comps; ++o) {
            double sum = 0;
            for (int k = 0; k < m.comps; ++k) sum += weights[o * m.comps + k] * m.values[e * m.comps + k];
            out.values[e * comps + o] = float(sum);
        }
    out.info = m.info;
    out.note("Applied " + std::to_string(comps) + "x" + std::to_string(m.comps) + " component transform");
    return out;
}

void scale(Matrix& m, const std::vector<double>& factors) {
    if (factors.size() != 1 && int(factors.size()) != m.comps)
        throw Error(std::to_string(factors.size()) + " scale factors for a matrix of " + std::to_string(m.comps) + " components");
    for (size_t i = 0; i < m.values.size(); ++i) m.values[i] = float(m.values[i] * factors[factors.size() == 1 ? 0 : i % m.comps]);
}

Matrix elementwise(const Matrix& a, const Matrix& b, ElementOp op) {
    bool oneComponent = b.comps == 1 && op != ElementOp::Add;
    if (a.rows != b.rows || a.cols != b.cols || (a.comps != b.comps && !oneComponent))
        throw Error("element by element, a " + size(a) + " matrix and a " + size(b) + " one do not match");
    Matrix out = a;
    bool zero = false;
    for (size_t e = 0; e < size_t(a.rows) * a.cols; ++e)
        for (int k = 0; k < a.comps; ++k) {
            float& x = out.values[e * a.comps + k];
            float y = b.values[e * b.comps + (oneComponent ? 0 : k)];
            switch (op) {
                case ElementOp::Add: x += y; break;
                case ElementOp::Multiply: x *= y; break;
                case ElementOp::Divide:
                    if (y == 0) x = 0, zero = true;
                    else x /= y;
                    break;
            }
        }
    if (zero) {
        warn("zero divisor(s) in element-wise division: those elements set to zero");
        out.info.push_back("WARNING: zero divide(s) corrupted results");
    }
    return out;
}

}  // namespace brume
