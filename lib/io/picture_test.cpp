#include "io/picture.h"

#include <gtest/gtest.h>

#include <OpenEXR/ImfRgbaFile.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "util/error.h"

using namespace brume;

namespace {

Picture gradient(int w, int h) {
    Picture p;
    p.width = w;
    p.height = h;
    p.pixels.resize(size_t(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* c = p.at(x, y);
            c[0] = float(x + 1);             // varies along rows: literals
            c[1] = 0.5f;                      // constant: runs
            c[2] = float(std::pow(10.0, y - 3));  // many exponents
        }
    return p;
}

Picture roundTrip(const Picture& p) {
    std::stringstream s;
    writeRadiancePicture(s, p);
    return readRadiancePicture(s, "test");
}

}  // namespace

// RGBE keeps 8 bits of mantissa: values come back within 1/256 of the largest component.
TEST(Picture, RunLengthEncodedRoundTripKeepsValuesToEightBits) {
    for (int w : {1, 7, 8, 9, 200, 300}) {
        Picture p = gradient(w, 5), q = roundTrip(p);
        ASSERT_EQ(q.width, w);
        ASSERT_EQ(q.height, 5);
        for (size_t i = 0; i < p.pixels.size(); i += 3)
            for (int c = 0; c < 3; ++c) {
                float big = std::max({p.pixels[i], p.pixels[i + 1], p.pixels[i + 2]});
                EXPECT_NEAR(q.pixels[i + c], p.pixels[i + c], big / 128) << "width " << w << " at " << i;
            }
    }
}

// Radiance pictures may be stored bottom-up or column by column; pixels land where they are displayed.
TEST(Picture, AnyScanOrderIsReadIntoDisplayOrder) {
    // 2 × 3 picture (width 2): flat RGBE, with the byte 'k' marking the pixel at display position k.
    auto pixel = [](int k) { return std::string{char(128), char(0), char(0), char(129 + k)}; };
    struct Case {
        const char* resolution;
        int order[6];  // display index (y*2 + x) of each stored pixel
    } cases[] = {{"-Y 3 +X 2", {0, 1, 2, 3, 4, 5}},
                 {"+Y 3 +X 2", {4, 5, 2, 3, 0, 1}},
                 {"-Y 3 -X 2", {1, 0, 3, 2, 5, 4}},
                 {"+X 2 -Y 3", {0, 2, 4, 1, 3, 5}}};
    for (const Case& c : cases) {
        std::string text = std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n") + c.resolution + "\n";
        for (int k : c.order) text += pixel(k);
        std::istringstream in(text);
        Picture p = readRadiancePicture(in, "test");
        for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(p.at(k % 2, k / 2)[0], std::ldexp(128.5f, 129 + k - 136)) << c.resolution;
    }
}

TEST(Picture, HeaderExposureAndAspectAreRead) {
    Picture p = gradient(3, 2);
    p.header = {"EXPOSURE=2", "PIXASPECT=1.5", "VIEW= -vtv"};
    Picture q = roundTrip(p);
    EXPECT_DOUBLE_EQ(q.exposure, 2);
    EXPECT_DOUBLE_EQ(q.pixelAspect, 1.5);
    EXPECT_EQ(q.header.size(), 3u);
}

TEST(Picture, TruncatedOrMalformedPicturesAreErrors) {
    std::stringstream s;
    writeRadiancePicture(s, gradient(50, 4));
    std::string whole = s.str();
    for (size_t cut : {size_t(5), size_t(20), whole.size() / 2, whole.size() - 1}) {
        std::istringstream in(whole.substr(0, cut));
        EXPECT_THROW(readRadiancePicture(in, "cut"), Error) << cut;
    }
    for (const char* text : {"P6\n", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 3\n",
                             "#?RADIANCE\nFORMAT=Radiance_spectra\n\n-Y 1 +X 1\n\1\2\3\4",
                             "#?RADIANCE\n\n-Y 2 -Y 3\n",
                             // promises 2^40 pixels: refused before anything is allocated
                             "#?RADIANCE\n\n-Y 1048576 +X 1048576\n\1\1\1\1",
                             // old run-length repeats (of 0 pixels) shifted past any scanline's length
                             "#?RADIANCE\n\n-Y 1 +X 9\n\4\4\4\4\1\1\1\0\1\1\1\0\1\1\1\0\1\1\1\1"}) {
        std::istringstream in(text);
        EXPECT_THROW(readRadiancePicture(in, "bad"), Error) << text;
    }
}

TEST(Picture, OpenExrPicturesAreReadAsLinearRgb) {
    std::string path = testing::TempDir() + "brume_picture_test.exr";
    {
        Imf::Rgba pixels[2 * 3];
        for (int k = 0; k < 6; ++k) pixels[k] = Imf::Rgba(float(k), 0.25f, 2.0f, 1.0f);
        Imf::RgbaOutputFile file(path.c_str(), 2, 3, Imf::WRITE_RGBA);
        file.setFrameBuffer(pixels, 1, 2);
        file.writePixels(3);
    }
    Picture p = readPicture(path);
    std::remove(path.c_str());
    ASSERT_EQ(p.width, 2);
    ASSERT_EQ(p.height, 3);
    EXPECT_FLOAT_EQ(p.at(1, 2)[0], 5);
    EXPECT_FLOAT_EQ(p.at(0, 1)[1], 0.25f);
    EXPECT_FLOAT_EQ(p.at(0, 0)[2], 2);
}

// Radiance 6.1 writes scanlines shorter than 17 or longer than 32767 pixels flat, the others run-length
// encoded after a (2, 2, length) mark; its resolution line pads the numbers to eight places.
TEST(Picture, ScanlinesAreLaidOutAsRadianceLaysThemOut) {
    for (int w : {16, 17}) {
        std::stringstream s;
        writeRadiancePicture(s, gradient(w, 2));
        std::string text = s.str(), resolution = "-Y        2 +X       " + std::to_string(w) + "\n";
        size_t data = text.find(resolution);
        ASSERT_NE(data, std::string::npos) << text;
        data += resolution.size();
        if (w == 16) EXPECT_EQ(text.size() - data, size_t(16 * 4 * 2));
        else EXPECT_EQ(text.substr(data, 4), (std::string{2, 2, 0, 17}));
    }
}

// As Radiance's reader does, the mark alone says a scanline is encoded, whatever its length.
TEST(Picture, EncodedScanlinesAreReadWhateverTheirLength) {
    std::string text = std::string("#?RADIANCE\n\n-Y 1 +X 3\n") + std::string{2, 2, 0, 3};
    for (char component : {char(128), char(0), char(0), char(129)}) text += std::string{char(128 + 3), component};
    std::istringstream in(text);
    Picture p = readRadiancePicture(in, "test");
    for (int x = 0; x < 3; ++x) EXPECT_FLOAT_EQ(p.at(x, 0)[0], 128.5f / 128);
}

// Primaries describe RGB: an XYZE picture says FORMAT=32-bit_rle_xyze and has none, as rpict's.
TEST(Picture, XyzPicturesSayXyzeAndHaveNoPrimaries) {
    Picture p = gradient(3, 2);
    p.xyz = true;
    p.header = {"rpict -x 3", "PRIMARIES= 0.6400 0.3300 0.2900 0.6000 0.1500 0.0600 0.3333 0.3333",
                "FORMAT=32-bit_rle_rgbe"};
    std::stringstream s;
    writeRadiancePicture(s, p);
    EXPECT_EQ(s.str().substr(0, s.str().find("\n\n")), "#?RADIANCE\nrpict -x 3\nFORMAT=32-bit_rle_xyze");
    EXPECT_TRUE(roundTrip(p).xyz);
}

// Radiance's encoder writes two or three equal bytes before a run as a short run rather than as literals.
TEST(Picture, ShortRunsBeforeARunAreEncodedAsRadianceEncodesThem) {
    Picture p;
    p.width = 17;
    p.height = 1;
    p.pixels.assign(17 * 3, 0.5f);                                 // exponent byte 128
    std::fill(p.pixels.begin(), p.pixels.begin() + 6, 0.25f);  // the first two pixels: exponent byte 127
    std::stringstream s;
    writeRadiancePicture(s, p);
    std::string scanline = s.str().substr(s.str().find("+X       17\n") + 12);
    EXPECT_EQ(scanline, (std::string{2, 2, 0, 17, char(145), char(128), char(145), char(128), char(145), char(128),
                                     char(130), char(127), char(143), char(128)}));
}

// A hyperspectral picture Radiance 6.1 wrote (rtrace -co -fac -x 2 -y 2, test/data/spectral/spic.hsr): its
// pixels are the spectra it was given (spic_values.txt there), to the 8-bit mantissas' precision.
TEST(HyperspectralPicture, ReadsWhatRadianceWrote) {
    HyperspectralPicture h = readHyperspectralPicture(std::string(BRUME_TEST_DATA) + "/spectral/spic.hsr");
    ASSERT_EQ(h.picture.width, 2);
    ASSERT_EQ(h.picture.height, 2);
    EXPECT_EQ(h.bands, 6);
    EXPECT_EQ(h.first, 700);
    EXPECT_EQ(h.last, 400);
    const float first[6] = {.1f, .2f, .4f, .6f, .8f, 1.f};  // the first pixel written: top left
    for (int b = 0; b < 6; ++b) EXPECT_NEAR(h.values[size_t(b)], first[b], 0.004) << "band " << b;
    std::string bytes = "#?RADIANCE\nNCOMP=6\nWAVELENGTH_SPLITS= 700 588 480 400\nFORMAT=Radiance_spectra\n\n"
                        "-Y 2 +X 2\n" + std::string(20, '\x80');
    std::istringstream truncated(bytes);
    EXPECT_THROW(readHyperspectralPicture(truncated, "t.hsr"), Error);
    std::istringstream rgbe("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n");
    EXPECT_THROW(readHyperspectralPicture(rgbe, "p.hdr"), Error);
    for (const char* header : {"NCOMP=3\nWAVELENGTH_SPLITS= 700 588 480 400\n", "NCOMP=6\n",
                               "NCOMP=6\nWAVELENGTH_SPLITS= 700 588 480 700\n", "NCOMP=6\nWAVELENGTH_SPLITS= 1e300 1 1 400\n"}) {
        std::istringstream bad("#?RADIANCE\n" + std::string(header) + "FORMAT=Radiance_spectra\n\n-Y 2 +X 2\n" +
                               std::string(28, '\x80'));
        EXPECT_THROW(readHyperspectralPicture(bad, "b.hsr"), Error) << header;
    }
}
