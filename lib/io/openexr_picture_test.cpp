#include "io/openexr_picture.h"

#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "exr_test_files.h"
#include "util/error.h"

using namespace brume;
using namespace brume_test;
namespace fs = std::filesystem;

TEST(OpenExrPicture, FloatPixelsComeBackExactlyAtOddResolutions) {
    ScratchDir dir;
    for (auto [w, h] : {std::pair{1, 1}, {7, 3}, {513, 257}}) {
        Picture p = rendered(w, h);
        writeOpenExrPicture(dir.file("p.exr"), p, ExrPixels::float32);
        Picture q = readPicture(dir.file("p.exr"));
        ASSERT_EQ(q.width, w);
        ASSERT_EQ(q.height, h);
        EXPECT_EQ(q.pixels, p.pixels) << w << "x" << h;
    }
}

// Half keeps 11 significant bits: round to nearest is within 2^-11 of the value.
TEST(OpenExrPicture, HalfPixelsComeBackWithinHalfPrecision) {
    ScratchDir dir;
    Picture p = rendered(7, 3);
    writeOpenExrPicture(dir.file("p.exr"), p, ExrPixels::half);
    Picture q = readPicture(dir.file("p.exr"));
    ASSERT_EQ(q.pixels.size(), p.pixels.size());
    for (size_t i = 0; i < p.pixels.size(); ++i) EXPECT_NEAR(q.pixels[i], p.pixels[i], p.pixels[i] / 2048) << i;
}

// A sun's disc is far beyond half's range: it stays the largest finite half rather than infinity.
TEST(OpenExrPicture, HalfClampsSunlitPixelsToTheLargestHalf) {
    ScratchDir dir;
    Picture p = rendered(1, 1);
    p.pixels = {1e7f, 70000.0f, -1e9f};
    writeOpenExrPicture(dir.file("sun.exr"), p, ExrPixels::half);
    EXPECT_EQ(readPicture(dir.file("sun.exr")).pixels, (std::vector<float>{65504, 65504, -65504}));
}

TEST(OpenExrPicture, RpictHeaderBecomesStandardAttributes) {
    ScratchDir dir;
    writeOpenExrPicture(dir.file("p.exr"), rendered(8, 8), ExrPixels::half);
    Imf::InputFile file(dir.file("p.exr").c_str());
    const Imf::Header& h = file.header();
    EXPECT_EQ(h.channels().findChannel("R")->type, Imf::HALF);
    EXPECT_EQ(h.compression(), Imf::ZIP_COMPRESSION);
    EXPECT_FLOAT_EQ(h.pixelAspectRatio(), float(1 / 1.125));  // OpenEXR's is width/height, Radiance's height/width
    ASSERT_TRUE(Imf::hasChromaticities(h));
    EXPECT_EQ(Imf::chromaticities(h).green, Imath::V2f(0.29f, 0.60f));
    EXPECT_EQ(Imf::chromaticities(h).white, Imath::V2f(0.3333f, 0.3333f));
    ASSERT_TRUE(Imf::hasWhiteLuminance(h));
    EXPECT_FLOAT_EQ(Imf::whiteLuminance(h), 179);
    EXPECT_EQ(Imf::capDate(h), "2026:11:23 15:02:04");
    EXPECT_FLOAT_EQ(Imf::utcOffset(h), -3600);  // UTC = local time + utcOffset
    EXPECT_EQ(stringAttribute(h, "comments"), "oconv s.rad\nrpict -x 8 -y 8 -vp 0 0 0 -vd 0 1 0");
    EXPECT_EQ(stringAttribute(h, "Software"), "RADIANCE 6.1a 2026-11-23 LBNL (6.1.bcffc2b52d)");
    EXPECT_EQ(stringAttribute(h, "view"), "-vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 45 -vv 45 -vo 0 -va 0 -vs 0 -vl 0");
    EXPECT_EQ(h.findTypedAttribute<Imf::StringAttribute>("radianceHeader"), nullptr);  // nothing else to keep
}

TEST(OpenExrPicture, RpictHeaderLinesComeBackInRpictsOrder) {
    ScratchDir dir;
    writeOpenExrPicture(dir.file("p.exr"), rendered(2, 2), ExrPixels::float32);
    Picture q = readPicture(dir.file("p.exr"));
    EXPECT_EQ(q.header, kRpictHeader);
    EXPECT_FLOAT_EQ(q.pixelAspect, 1.125);  // pixelAspectRatio is a float
    EXPECT_FALSE(q.xyz);
}

// pfilt's header lines: another command, an exposure, a second PIXASPECT= (Radiance multiplies them) and a
// variable OpenEXR has no name for.
TEST(OpenExrPicture, ExposureAspectAndOtherLinesSurvive) {
    ScratchDir dir;
    std::vector<std::string> header = {"rpict -vf v.vf", "FRAME=3", "PIXASPECT=2", "pfilt -e 2", "EXPOSURE=2",
                                       "PIXASPECT=1.5"};
    writeOpenExrPicture(dir.file("p.exr"), rendered(3, 2, header), ExrPixels::half);
    {
        Imf::InputFile file(dir.file("p.exr").c_str());
        EXPECT_FLOAT_EQ(file.header().pixelAspectRatio(), float(1 / 3.0));
        EXPECT_FLOAT_EQ(Imf::whiteLuminance(file.header()), 179 / 2.0f);  // pixels are twice the radiance
        EXPECT_EQ(stringAttribute(file.header(), "radianceHeader"), "FRAME=3");
    }
    Picture q = readPicture(dir.file("p.exr"));
    EXPECT_EQ(q.header, (std::vector<std::string>{"rpict -vf v.vf", "pfilt -e 2", "FRAME=3", "PIXASPECT=3.000000",
                                                  "EXPOSURE=2.0000e+00", "PRIMARIES= 0.6400 0.3300 0.2900 0.6000 "
                                                                         "0.1500 0.0600 0.3333 0.3333"}));
    EXPECT_FLOAT_EQ(q.pixelAspect, 3);
    EXPECT_DOUBLE_EQ(q.exposure, 2);
}

// OpenEXR's convention for CIE XYZ: X, Y, Z in R, G, B, told apart by the chromaticities; Y in cd/m² as
// Radiance 6.1's XYZE holds it, so a white luminance of 1 (179 for RGB).
TEST(OpenExrPicture, XyzPicturesUseOpenExrsXyzChromaticities) {
    ScratchDir dir;
    Picture p = rendered(2, 2, {"rpict -x 2 -y 2", "PRIMARIES= 0.6400 0.3300 0.2900 0.6000 0.1500 0.0600 0.3333 0.3333"});
    p.xyz = true;
    writeOpenExrPicture(dir.file("xyz.exr"), p, ExrPixels::float32);
    {
        Imf::InputFile file(dir.file("xyz.exr").c_str());
        EXPECT_EQ(Imf::chromaticities(file.header()).red, Imath::V2f(1, 0));
        EXPECT_EQ(Imf::chromaticities(file.header()).blue, Imath::V2f(0, 0));
        EXPECT_FLOAT_EQ(Imf::whiteLuminance(file.header()), 1);
    }
    Picture q = readPicture(dir.file("xyz.exr"));
    EXPECT_TRUE(q.xyz);
    EXPECT_EQ(q.header, std::vector<std::string>{"rpict -x 2 -y 2"});  // no PRIMARIES= for XYZ
    EXPECT_EQ(q.pixels, p.pixels);
}

// Other programs' files carry only OpenEXR's attributes: their pixel aspect still becomes PIXASPECT=.
TEST(OpenExrPicture, ForeignPixelAspectBecomesAPixaspectLine) {
    ScratchDir dir;
    {
        Imf::Rgba pixel(1, 2, 3, 1);
        Imf::Header h(1, 1, 2.0f);
        Imf::RgbaOutputFile file(dir.file("wide.exr").c_str(), h, Imf::WRITE_RGB);
        file.setFrameBuffer(&pixel, 1, 1);
        file.writePixels(1);
    }
    Picture q = readPicture(dir.file("wide.exr"));
    EXPECT_EQ(q.header, std::vector<std::string>{"PIXASPECT=0.500000"});
    EXPECT_EQ(q.pixels, (std::vector<float>{1, 2, 3}));
}

// A data window away from the origin (a crop of a larger frame) is the picture.
TEST(OpenExrPicture, DataWindowAwayFromTheOriginIsThePicture) {
    ScratchDir dir;
    {
        std::vector<float> rgb = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
        Imath::Box2i window({-3, 5}, {-2, 6});
        Imf::Header h(Imath::Box2i({0, 0}, {9, 9}), window);
        Imf::FrameBuffer frame;
        const char* name[] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c) {
            h.channels().insert(name[c], Imf::Channel(Imf::FLOAT));
            frame.insert(name[c], Imf::Slice::Make(Imf::FLOAT, &rgb[c], window, 3 * sizeof(float), 6 * sizeof(float)));
        }
        Imf::OutputFile file(dir.file("crop.exr").c_str(), h);
        file.setFrameBuffer(frame);
        file.writePixels(2);
    }
    Picture q = readPicture(dir.file("crop.exr"));
    ASSERT_EQ(q.width, 2);
    ASSERT_EQ(q.height, 2);
    EXPECT_EQ(q.pixels, (std::vector<float>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
}

TEST(OpenExrPicture, FailedWriteLeavesNothingUnderAnyName) {
    ScratchDir dir;
    std::ofstream(dir.file("not_a_dir")) << "x";
    try {
        writeOpenExrPicture(dir.file("not_a_dir") + "/p.exr", rendered(2, 2), ExrPixels::half);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write " + dir.file("not_a_dir") + "/p.exr: Not a directory");
    }
    // The picture is complete when renaming fails (a directory holds the name): the temporary goes too.
    fs::create_directory(dir.file("taken.exr"));
    EXPECT_THROW(writeOpenExrPicture(dir.file("taken.exr"), rendered(2, 2), ExrPixels::half), Error);
    EXPECT_EQ(dir.entries(), 2u);
    EXPECT_THROW(writeOpenExrPicture(dir.file("p.exr"), rendered(2, 2, {"PIXASPECT=0"}), ExrPixels::half), Error);
    EXPECT_EQ(dir.entries(), 2u);
}

TEST(OpenExrPicture, WriteReplacesAnExistingPictureWhole) {
    ScratchDir dir;
    writeOpenExrPicture(dir.file("p.exr"), rendered(513, 257), ExrPixels::float32);
    writeOpenExrPicture(dir.file("p.exr"), rendered(1, 1), ExrPixels::half);
    EXPECT_EQ(readPicture(dir.file("p.exr")).width, 1);
    EXPECT_EQ(dir.entries(), 1u);
}
