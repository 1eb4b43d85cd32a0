// A Klems BSDF's transmission matrix from its front transmission, or by reciprocity from its back one alone:
// test/data/bsdf/prism_quarter.xml's back transmission is its front one's reciprocal, so the two ways give the
// same matrix (its values against Radiance's rmtxop: test/daymtx_cli_test.cpp).
#include "matrix/bsdf_matrix.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "scratch_dir.h"
#include "util/error.h"

using namespace brume;

namespace {

const std::string kFile = std::string(BRUME_TEST_DATA) + "/bsdf/prism_quarter.xml";

// A copy of file `from` without its WavelengthDataBlock of `direction`, written as `name`.
std::string without(const std::string& from, const std::string& direction, const std::string& name) {
    std::ifstream in(from);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    size_t at = s.find("<WavelengthDataDirection>" + direction + "</WavelengthDataDirection>");
    size_t begin = s.rfind("<WavelengthDataBlock>", at), end = s.find("</WavelengthDataBlock>", at);
    s.erase(begin, end + std::string("</WavelengthDataBlock>").size() - begin);
    std::string path = (brume_test::scratchDir("bsdf_matrix") / name).string();
    std::ofstream(path) << s;
    return path;
}

}  // namespace

TEST(BsdfMatrix, ReciprocityGivesTheFrontTransmissionsMatrix) {
    Matrix front = transmissionMatrix(kFile), back = transmissionMatrix(without(kFile, "Transmission Front", "back.xml"));
    ASSERT_EQ(front.rows, 41);
    ASSERT_EQ(front.cols, 41);
    ASSERT_EQ(back.rows, 41);
    ASSERT_EQ(back.cols, 41);
    ASSERT_EQ(back.comps, 3);
    double largest = 0;
    for (float v : front.values) largest = std::max(largest, double(v));
    for (size_t i = 0; i < front.values.size(); ++i) ASSERT_NEAR(back.values[i], front.values[i], 1e-5 * largest) << i;
}

TEST(BsdfMatrix, AFileWithoutTransmissionIsRefused) {
    std::string path = without(without(kFile, "Transmission Front", "back.xml"), "Transmission Back", "none.xml");
    EXPECT_THROW(transmissionMatrix(path), Error);
    EXPECT_TRUE(isBsdfFile("a.XML"));
    EXPECT_FALSE(isBsdfFile("xml"));
}
