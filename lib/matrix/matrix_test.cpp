#include "matrix/matrix.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "matrix/matrix_file.h"
#include "util/error.h"

namespace brume {
namespace {

Matrix filled(int rows, int cols, int comps, float start = 1) {
    Matrix m(rows, cols, comps);
    for (size_t i = 0; i < m.values.size(); ++i) m.values[i] = start + float(i);
    return m;
}

// Each component its own product, against the sums written out.
TEST(Matrix, MultipliesComponentByComponent) {
    Matrix a = filled(2, 3, 2), b = filled(3, 2, 2, 10);
    Matrix c = multiply(a, b);
    ASSERT_EQ(c.rows, 2);
    ASSERT_EQ(c.cols, 2);
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) {
                double sum = 0;
                for (int n = 0; n < 3; ++n) sum += a.at(i, n)[k] * b.at(n, j)[k];
                EXPECT_FLOAT_EQ(c.at(i, j)[k], float(sum));
            }
    EXPECT_THROW(multiply(a, a), Error);
}

TEST(Matrix, TransposesTransformsAndScales) {
    Matrix a = filled(2, 3, 3);
    a.info = {"made by hand"};
    Matrix t = transposed(a);
    EXPECT_EQ(t.info.back(), "Transposed rows and columns");
    Matrix back = transposed(t);
    EXPECT_EQ(back.values, a.values);
    Matrix y = transformed(a, {0.5, 0.25, 0.25});
    ASSERT_EQ(y.comps, 1);
    EXPECT_FLOAT_EQ(y.at(1, 2)[0], 0.5f * a.at(1, 2)[0] + 0.25f * (a.at(1, 2)[1] + a.at(1, 2)[2]));
    EXPECT_THROW(transformed(a, {1, 2}), Error);
    scale(a, {1, 2, 3});
    EXPECT_FLOAT_EQ(a.at(0, 1)[2], 3 * 6.f);
    EXPECT_THROW(scale(a, {1, 2}), Error);
    Matrix plain = filled(1, 1, 3);
    EXPECT_TRUE(transposed(plain).info.empty());  // no history, no note (rmtxop's rule)
}

TEST(Matrix, ElementwiseDivisionByZeroGivesZeroAndSaysSo) {
    Matrix a = filled(1, 2, 3), b(1, 2, 1);
    b.values = {2, 0};
    Matrix q = elementwise(a, b, ElementOp::Divide);
    EXPECT_FLOAT_EQ(q.at(0, 0)[2], 1.5f);
    EXPECT_EQ(q.at(0, 1)[0], 0.f);
    EXPECT_EQ(q.info.back(), "WARNING: zero divide(s) corrupted results");
    EXPECT_THROW(elementwise(a, b, ElementOp::Add), Error);  // a sum needs every component
}

std::string written(const Matrix& m, MatrixFormat f) {
    std::FILE* tmp = std::tmpfile();
    writeMatrix(tmp, m, f, AsciiLayout::Rmtxop, {"test"});
    std::rewind(tmp);
    std::string bytes;
    char buffer[4096];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, tmp)) > 0;) bytes.append(buffer, n);
    std::fclose(tmp);
    return bytes;
}

// Written and read back in every format, the same values (RGBE to its 1 % precision).
TEST(MatrixFile, RoundTripsInEveryFormat) {
    Matrix m = filled(3, 4, 3, 0.25f);
    m.info = {"made by hand"};
    for (MatrixFormat f : {MatrixFormat::Ascii, MatrixFormat::Float, MatrixFormat::Double, MatrixFormat::Rgbe}) {
        MatrixFormat stored;
        Matrix r = parseMatrix(written(m, f), "test", {}, &stored);
        EXPECT_EQ(stored, f);
        ASSERT_EQ(r.rows, 3);
        ASSERT_EQ(r.cols, 4);
        ASSERT_EQ(r.comps, 3);
        // RGBE: 8 bits of mantissa under the element's largest component.
        for (size_t i = 0; i < m.values.size(); ++i)
            EXPECT_NEAR(r.values[i], m.values[i], f == MatrixFormat::Rgbe ? 0.01 * m.values[i / 3 * 3 + 2] : 1e-6 * m.values[i]);
        EXPECT_NE(std::find(r.info.begin(), r.info.end(), "made by hand"), r.info.end());
    }
}

TEST(MatrixFile, ReadsHeaderlessSwappedAndExposedInputs) {
    Matrix v = parseMatrix("1 2 3 4 5 6\n", "sky", MatrixShape{std::nullopt, 1, 3});
    EXPECT_EQ(v.rows, 2);
    EXPECT_EQ(v.cols, 1);
    float big[2];
    unsigned char bytes[8];
    big[0] = 1.5f, big[1] = -2.f;
    std::memcpy(bytes, big, 8);
    for (int k = 0; k < 2; ++k) std::reverse(bytes + 4 * k, bytes + 4 * k + 4);
    std::string swapped = "#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=1\nBigEndian=1\nFORMAT=float\n\n" + std::string(reinterpret_cast<char*>(bytes), 8);
    Matrix s = parseMatrix(swapped, "swapped");
    EXPECT_EQ(s.values, (std::vector<float>{1.5f, -2.f}));
    Matrix e = parseMatrix("#?RADIANCE\nNCOMP=1\nNROWS=1\nNCOLS=2\nEXPOSURE=2\nFORMAT=ascii\n\n4 8\n", "exposed");
    EXPECT_EQ(e.values, (std::vector<float>{2.f, 4.f}));
}

TEST(MatrixFile, RefusesMalformedInput) {
    for (const char* bad : {"#?RADIANCE\nNROWS=2\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n1 2 3\n",
                            "#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n1 x\n",
                            "#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n1 nan\n",
                            "#?RADIANCE\nNROWS=1\nNCOLS=2\nNCOMP=1\nFORMAT=float\n\n\1\2\3",
                            "#?RADIANCE\nNROWS=-1\nFORMAT=ascii\n\n1\n", "#?RADIANCE\nFORMAT=bytes\n\n1\n",
                            "#?RADIANCE\nNROWS=1\n", "#?RADIANCE\nNROWS=1000000\nNCOLS=1000000\nNCOMP=3\nFORMAT=float\n\n"})
        EXPECT_THROW(parseMatrix(bad, "bad"), Error) << bad;
}

}  // namespace
}  // namespace brume
