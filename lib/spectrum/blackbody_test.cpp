// Black bodies for flames: the table flames read between its entries against Planck's law itself, and the
// RGB of black bodies outside the gamut (below 2000 K) without the grey that Radiance's desaturation adds.
#include "spectrum/blackbody.h"

#include <gtest/gtest.h>

#include "spectral_sampling_scope.h"
#include "spectrum/colorimetry.h"

using namespace brume;

// Between entries 25 K apart, every band within 2e-4 of blackbody() (the interpolation in ln B over 1/T is
// exact for Wien's law at one wavelength, nearly so for a band's average; a linear one was 1 % off at 1500 K), or
// 1e-3 of the brightest band (RGB's green near 1000 K, where it leaves 0, is not Wien-like), down to bands
// 1e-30 of the brightest, from 600 K (below it, at 1e-10 of a 1500 K flame's light, RGB's red is 1 % off at 312 K);
// the entries themselves exactly.
TEST(BlackbodyTable, InterpolatesPlanckBetweenItsEntries) {
    for (int bands : {3, 41}) {
        SpectralSamplingScope sampling(bands);
        BlackbodyTable table;
        for (double kelvin : {612.5, 700.0, 1012.5, 1234.0, 1512.5, 2987.5, 5990.0}) {
            Spectrum exact = blackbody(kelvin), tabled = table.at(kelvin);
            for (int c = 0; c < bands; ++c)
                if (exact[c] > 1e-30 * exact.maxValue())
                    EXPECT_NEAR(tabled[c], exact[c], 2e-4 * exact[c] + 1e-3 * exact.maxValue()) << bands << " bands, " << kelvin << " K, band " << c;
        }
        EXPECT_EQ(table.at(1500)[0], blackbody(1500)[0]);
        EXPECT_TRUE(table.at(0).isBlack());
        EXPECT_TRUE(table.at(-40).isBlack());
        EXPECT_EQ(table.at(1e9)[0], blackbody(BlackbodyTable::kHottest)[0]);
    }
}

// Below 2000 K a black body lies outside Radiance's gamut (negative blue; below 900 K negative green too): its
// RGB has none of the missing primaries (desaturation toward grey gave a 700 K flame 8 % of its red in blue;
// Planck's blue is 1e-9 of its red there), and keeps its luminance (Y) exactly.
TEST(Blackbody, RgbOutsideTheGamutAddsNoGreyAndKeepsItsLuminance) {
    for (double kelvin : {600.0, 700.0, 1000.0, 1500.0}) {
        Spectrum rgb = blackbody(kelvin);
        Color3 xyz{0, 0, 0};
        {
            SpectralSamplingScope bands(81, 380, 780);
            xyz = toXyz(blackbody(kelvin));
        }
        EXPECT_EQ(rgb[2], 0) << kelvin << " K";
        if (kelvin < 900) EXPECT_EQ(rgb[1], 0) << kelvin << " K";
        EXPECT_GT(rgb[0], 0);
        EXPECT_NEAR(photopic(rgb), xyz[1], 2e-3 * xyz[1]) << kelvin << " K";  // (81 bands against 1 nm bins)
    }
    Spectrum hot = blackbody(3000);  // inside the gamut: every primary
    EXPECT_GT(hot[2], 0);
}

// Radiance's own clipping brings negatives to 0, never below (the mix rounded to −1e−18 in a 1000 K flame's blue).
TEST(Colorimetry, ClippedRgbIsNeverNegative) {
    for (double kelvin : {600.0, 800.0, 1000.0, 1200.0, 1500.0}) {
        Color3 xyz{0, 0, 0};
        {
            SpectralSamplingScope bands(81, 380, 780);
            xyz = toXyz(blackbody(kelvin));
        }
        for (double c : xyzToClippedRgb(xyz)) EXPECT_GE(c, 0) << kelvin << " K";
    }
}
