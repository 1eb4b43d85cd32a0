#include "io/spectral_picture.h"

#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <fstream>

#include "exr_test_files.h"
#include "util/error.h"

using namespace brume;
using namespace brume_test;

namespace {

// The centres of rpict's n bands of equal width between lo and hi nm, in Radiance's order: longest first.
std::vector<double> bandCentres(int n, double lo = 380, double hi = 780) {
    std::vector<double> c;
    for (int i = 0; i < n; ++i) c.push_back(hi - (i + 0.5) * (hi - lo) / n);
    return c;
}

SpectralPixels spectrum(const Picture& p, std::vector<double> wavelengths) {
    return {wavelengths, distinctValues(size_t(p.width) * p.height * wavelengths.size())};
}

std::vector<std::string> channelNames(const std::string& path) {
    Imf::InputFile file(path.c_str());
    std::vector<std::string> names;
    for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c) names.push_back(c.name());
    return names;
}

}  // namespace

TEST(SpectralPicture, FloatBandsAndPictureComeBackExactly) {
    ScratchDir dir;
    Picture p = rendered(5, 3);
    SpectralPixels s = spectrum(p, bandCentres(8));
    writeSpectralOpenExrPicture(dir.file("s.exr"), p, s, ExrPixels::float32);
    auto [q, t] = readSpectralOpenExrPicture(dir.file("s.exr"));
    EXPECT_EQ(q.width, 5);
    EXPECT_EQ(q.height, 3);
    EXPECT_EQ(q.pixels, p.pixels);
    EXPECT_EQ(q.header, kRpictHeader);
    EXPECT_EQ(t.wavelengths, (std::vector<double>{755, 705, 655, 605, 555, 505, 455, 405}));
    EXPECT_EQ(t.values, s.values);
}

// The layout's names and attributes, beside R, G, B and the header's attributes as writeOpenExrPicture writes them.
TEST(SpectralPicture, ChannelsAndAttributesFollowTheLayout) {
    ScratchDir dir;
    Picture p = rendered(2, 2);
    writeSpectralOpenExrPicture(dir.file("s.exr"), p, spectrum(p, bandCentres(4)), ExrPixels::half);
    // OpenEXR lists channels by name.
    EXPECT_EQ(channelNames(dir.file("s.exr")),
              (std::vector<std::string>{"B", "G", "R", "S0.430,000000nm", "S0.530,000000nm", "S0.630,000000nm",
                                        "S0.730,000000nm"}));
    Imf::InputFile file(dir.file("s.exr").c_str());
    const Imf::Header& h = file.header();
    EXPECT_EQ(h.channels().findChannel("S0.530,000000nm")->type, Imf::HALF);
    EXPECT_EQ(stringAttribute(h, "spectralLayoutVersion"), "1.0");
    EXPECT_EQ(stringAttribute(h, "emissiveUnits"), "W.m^-2.sr^-1");
    EXPECT_EQ(h.findTypedAttribute<Imf::StringAttribute>("polarisationHandedness"), nullptr);
    EXPECT_EQ(stringAttribute(h, "comments"), "oconv s.rad\nrpict -x 8 -y 8 -vp 0 0 0 -vd 0 1 0");
    EXPECT_FLOAT_EQ(h.pixelAspectRatio(), float(1 / 1.125));
}

// -cs 12 over 380-780 nm: bands 33.3 nm wide, centred on thirds of a nanometre, named to six decimals.
TEST(SpectralPicture, NonIntegerCentresAreNamedToSixDecimals) {
    ScratchDir dir;
    Picture p = rendered(3, 2);
    SpectralPixels s = spectrum(p, bandCentres(12));
    writeSpectralOpenExrPicture(dir.file("s.exr"), p, s, ExrPixels::float32);
    std::vector<std::string> names = channelNames(dir.file("s.exr"));
    EXPECT_EQ(names[3], "S0.396,666667nm");
    EXPECT_EQ(names.back(), "S0.763,333333nm");
    auto [q, t] = readSpectralOpenExrPicture(dir.file("s.exr"));
    ASSERT_EQ(t.wavelengths.size(), 12u);
    for (size_t i = 0; i < 12; ++i) EXPECT_NEAR(t.wavelengths[i], s.wavelengths[i], 5e-7) << i;
    EXPECT_EQ(t.values, s.values);
}

TEST(SpectralPicture, FortyOneAndEightyOneBandsComeBackInRadiancesOrder) {
    ScratchDir dir;
    for (int n : {41, 81}) {
        Picture p = rendered(7, 4);
        SpectralPixels s = spectrum(p, bandCentres(n));
        writeSpectralOpenExrPicture(dir.file("s.exr"), p, s, ExrPixels::float32);
        EXPECT_EQ(channelNames(dir.file("s.exr")).size(), size_t(3 + n));
        auto [q, t] = readSpectralOpenExrPicture(dir.file("s.exr"));
        ASSERT_EQ(t.wavelengths.size(), size_t(n));
        for (int i = 0; i < n; ++i) EXPECT_NEAR(t.wavelengths[i], s.wavelengths[i], 5e-7) << n << " bands, band " << i;
        EXPECT_EQ(t.values, s.values) << n << " bands";
        EXPECT_EQ(q.pixels, p.pixels);
    }
}

// Bands given shortest first are stored alike and read back longest first.
TEST(SpectralPicture, BandsAreReadLongestFirstWhateverTheirOrderWhenWritten) {
    ScratchDir dir;
    Picture p = rendered(1, 1);
    writeSpectralOpenExrPicture(dir.file("s.exr"), p, {{450, 550, 1000}, {1, 2, 3}}, ExrPixels::float32);
    auto [q, t] = readSpectralOpenExrPicture(dir.file("s.exr"));
    EXPECT_EQ(t.wavelengths, (std::vector<double>{1000, 550, 450}));
    EXPECT_EQ(t.values, (std::vector<float>{3, 2, 1}));
}

TEST(SpectralPicture, HalfBandsComeBackWithinHalfPrecisionAndClampAtTheLargestHalf) {
    ScratchDir dir;
    Picture p = rendered(4, 3);
    SpectralPixels s = spectrum(p, bandCentres(5));
    s.values[0] = 1e7f;
    s.values[1] = 70000;
    s.values[2] = -1e9f;
    p.pixels[0] = 1e7f;
    writeSpectralOpenExrPicture(dir.file("s.exr"), p, s, ExrPixels::half);
    auto [q, t] = readSpectralOpenExrPicture(dir.file("s.exr"));
    EXPECT_EQ((std::vector<float>{t.values[0], t.values[1], t.values[2]}), (std::vector<float>{65504, 65504, -65504}));
    EXPECT_EQ(q.pixels[0], 65504);
    ASSERT_EQ(t.values.size(), s.values.size());
    for (size_t i = 3; i < s.values.size(); ++i) EXPECT_NEAR(t.values[i], s.values[i], s.values[i] / 2048) << i;
}

// Any reader of OpenEXR pictures, readPicture among them, finds the picture in R, G, B.
TEST(SpectralPicture, ReadsAsAnOrdinaryPicture) {
    ScratchDir dir;
    Picture p = rendered(3, 3);
    writeSpectralOpenExrPicture(dir.file("s.exr"), p, spectrum(p, bandCentres(9)), ExrPixels::float32);
    Picture q = readPicture(dir.file("s.exr"));
    EXPECT_EQ(q.pixels, p.pixels);
    EXPECT_EQ(q.header, kRpictHeader);
}

// Other writers' spellings: an exponent, another prefix, a frequency. Polarisation (S1), reflectance (T.) and
// channels of other layers are not bands.
TEST(SpectralPicture, ReadsEverySpellingOfAnEmissiveBand) {
    ScratchDir dir;
    const std::vector<std::string> names = {"S0.5,5E2nm", "S0.0,6um", "S0.600THz", "S1.550nm", "T.550nm", "S0.nm", "Y"};
    std::vector<float> values = {1, 2, 3, 4, 5, 6, 7};
    {
        Imf::Header h(1, 1);
        Imf::FrameBuffer frame;
        for (size_t c = 0; c < names.size(); ++c) {
            h.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
            frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&values[c]), sizeof(float), sizeof(float)));
        }
        Imf::OutputFile file(dir.file("other.exr").c_str(), h);
        file.setFrameBuffer(frame);
        file.writePixels(1);
    }
    auto [q, t] = readSpectralOpenExrPicture(dir.file("other.exr"));
    ASSERT_EQ(t.wavelengths.size(), 3u);
    EXPECT_DOUBLE_EQ(t.wavelengths[0], 600);
    EXPECT_EQ(t.wavelengths[1], 550);
    EXPECT_NEAR(t.wavelengths[2], 299792458 / 600e12 * 1e9, 1e-9);
    EXPECT_EQ(t.values, (std::vector<float>{2, 1, 3}));
    EXPECT_EQ(q.pixels, (std::vector<float>{7, 7, 7}));  // luminance alone, as grey
}

TEST(SpectralPicture, PicturesWithoutBandsAreRefused) {
    ScratchDir dir;
    writeOpenExrPicture(dir.file("rgb.exr"), rendered(2, 2), ExrPixels::half);
    try {
        readSpectralOpenExrPicture(dir.file("rgb.exr"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), dir.file("rgb.exr") + ": no spectral channels (S0.…nm)");
    }
}

TEST(SpectralPicture, FailedWriteLeavesNothingUnderAnyName) {
    ScratchDir dir;
    Picture p = rendered(2, 2);
    SpectralPixels s = spectrum(p, bandCentres(41));
    std::ofstream(dir.file("not_a_dir")) << "x";
    try {
        writeSpectralOpenExrPicture(dir.file("not_a_dir") + "/s.exr", p, s, ExrPixels::half);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write " + dir.file("not_a_dir") + "/s.exr: Not a directory");
    }
    std::filesystem::create_directory(dir.file("taken.exr"));
    EXPECT_THROW(writeSpectralOpenExrPicture(dir.file("taken.exr"), p, s, ExrPixels::float32), Error);
    EXPECT_EQ(dir.entries(), 2u);
    SpectralPixels truncated = s;
    truncated.values.pop_back();
    EXPECT_THROW(writeSpectralOpenExrPicture(dir.file("s.exr"), p, truncated, ExrPixels::half), Error);
    try {
        writeSpectralOpenExrPicture(dir.file("s.exr"), p, {{550, 600, 550.0000001}, std::vector<float>(12)},
                                    ExrPixels::half);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write " + dir.file("s.exr") + ": two bands named S0.550,000000nm");
    }
    EXPECT_EQ(dir.entries(), 2u);
}
