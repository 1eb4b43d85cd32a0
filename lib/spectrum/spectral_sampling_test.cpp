#include "spectrum/spectral_sampling.h"

#include <gtest/gtest.h>

#include "spectral_sampling_scope.h"
#include "spectrum/spectrum.h"
#include "util/error.h"

using namespace brume;

TEST(SpectralSampling, BandsRunFromTheLongestWavelength) {
    SpectralSampling s{40, 780, 380};
    EXPECT_EQ(s.band(0), (std::array<double, 2>{780, 770}));
    EXPECT_EQ(s.band(39), (std::array<double, 2>{390, 380}));
    EXPECT_DOUBLE_EQ(s.bandCentre(1), 765);
}

TEST(SpectralSampling, RgbBandsAreRadiancesPartitions) {
    SpectralSampling rgb;
    EXPECT_EQ(rgb.splits(), (std::array<double, 4>{780, 588, 480, 380}));
    EXPECT_EQ(rgb.band(1), (std::array<double, 2>{588, 480}));
    // A range that misses a primary's peak is split in thirds (Radiance's setspectrsamp).
    SpectralSampling red{12, 780, 600};
    EXPECT_DOUBLE_EQ(red.splits()[1], 720);
}

TEST(SpectralSampling, SettingItSetsSpectraChannelsAndBrightness) {
    {
        SpectralSamplingScope bands(81);
        EXPECT_EQ(Spectrum::defaultChannels(), 81);
        EXPECT_EQ(Spectrum(1.f).size(), 81);
        EXPECT_NEAR(brightness(Spectrum(2.f)), 2, 1e-5);  // photopic weights sum to 1
        Spectrum green(0.f);
        green[40] = 1;  // 580 nm: near V(λ)'s peak, more than an equal share
        EXPECT_GT(brightness(green), 1.5 / 81);
    }
    EXPECT_EQ(Spectrum::defaultChannels(), 3);
}

TEST(SpectralSampling, RefusesWhatRadianceRefuses) {
    auto message = [](SpectralSampling s) {
        try {
            setSpectralSampling(s);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message({2, 780, 380}).find("at least 3"), std::string::npos);
    EXPECT_NE(message({97, 780, 380}).find("at most 96"), std::string::npos);
    EXPECT_NE(message({12, 520, 500}).find("50 nm"), std::string::npos);
    EXPECT_EQ(spectralSampling(), SpectralSampling{});
    setSpectralSampling({12, 380, 780});  // extrema in either order
    EXPECT_EQ(spectralSampling().longest, 780);
    setSpectralSampling({});
}
