#include "material/bsdf_klems.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sampling/random.h"

namespace brume {
namespace {

const std::string kFile = std::string(BRUME_TEST_DATA) + "/bsdf/prism_quarter.xml";

dvec3 polar(double thetaDeg, double phiDeg, bool front = true) {
    double t = thetaDeg * M_PI / 180, p = phiDeg * M_PI / 180;
    return {std::cos(p) * std::sin(t), std::sin(p) * std::sin(t), (front ? 1 : -1) * std::cos(t)};
}

class KlemsBsdfTest : public ::testing::Test {
protected:
    KlemsBsdf bsdf{readKlemsXml(kFile, kFile)};
};

// make_klems.py puts a floor of 0.03/sr under the transmission and 0.05/sr under the front reflection.
TEST_F(KlemsBsdfTest, TheSmallestValueIsSplitOffAsLambertian) {
    EXPECT_NEAR(bsdf.diffuseTransmission(true)[0], M_PI * 0.03, 2e-4);
    EXPECT_NEAR(bsdf.diffuseTransmission(false)[1], M_PI * 0.03, 2e-4);
    EXPECT_NEAR(bsdf.diffuseReflection(true)[2], M_PI * 0.05, 2e-4);
    EXPECT_TRUE(bsdf.transmits());
}

TEST_F(KlemsBsdfTest, TransmissionIsReciprocal) {
    Random rng(7, 0);
    for (int k = 0; k < 200; ++k) {
        dvec3 a = polar(89 * rng.uniform(), 360 * rng.uniform()), b = polar(89 * rng.uniform(), 360 * rng.uniform(), false);
        EXPECT_FLOAT_EQ(bsdf.value(a, b)[0], bsdf.value(b, a)[0]);
    }
}

// The straight-through patch is bent toward +y (the up vector) by make_klems.py.
TEST_F(KlemsBsdfTest, TransmissionPeaksUpward) {
    dvec3 view = polar(0, 0);
    EXPECT_GT(bsdf.value(view, polar(18, 90, false))[0], 2 * bsdf.value(view, polar(18, 270, false))[0]);
}

TEST_F(KlemsBsdfTest, HemisphericalSumsStayBelowOne) {
    const KlemsBasis& b = *KlemsBasis::standard("LBNL/Klems Quarter");
    for (bool front : {true, false})
        for (int p = 0; p < b.size(); ++p) {
            dvec3 view = KlemsSide{front, false}.direction(b, p, 0.5, 0.5);
            double t = bsdf.albedo(view, true) + luminance(bsdf.diffuseTransmission(front));
            double r = bsdf.albedo(view, false) + luminance(bsdf.diffuseReflection(front));
            EXPECT_LE(t, 1);
            EXPECT_LE(t + r, 1);
            EXPECT_GT(bsdf.albedo(view, true), 0.1);
        }
}

// A sample's value over its density is the albedo (the weight Radiance gives it), and the density
// integrates to one over the side it samples.
TEST_F(KlemsBsdfTest, SamplesWeighTheAlbedo) {
    Random rng(3, 0);
    for (dvec3 view : {polar(30, 40), polar(70, 200, false)}) {
        for (bool transmit : {false, true}) {
            double albedo = bsdf.albedo(view, transmit);
            for (int k = 0; k < 2000; ++k) {
                auto l = bsdf.sample(view, transmit, rng.uniform(), rng.uniform());
                ASSERT_TRUE(l);
                EXPECT_EQ((l->z > 0) == (view.z > 0), !transmit);
                double pdf = bsdf.projectedPdf(view, *l);
                ASSERT_GT(pdf, 0);
                EXPECT_NEAR(bsdf.value(view, *l)[0] / pdf, albedo, 1e-4 * albedo);
            }
            // The density is constant on each patch: ∫ pdf dΩ⊥ = Σ pdf × projected solid angle.
            const KlemsBasis& b = *KlemsBasis::standard("LBNL/Klems Quarter");
            bool lightFront = (view.z > 0) != transmit;
            double integral = 0;
            for (int p = 0; p < b.size(); ++p)
                integral += bsdf.projectedPdf(view, KlemsSide{lightFront, false}.direction(b, p, 0.5, 0.5)) *
                            b.projectedSolidAngle(p);
            EXPECT_NEAR(integral, 1, 1e-9);
        }
    }
}

}  // namespace
}  // namespace brume
