#include "material/klems_basis.h"

#include <gtest/gtest.h>

#include <cmath>

namespace brume {
namespace {

dvec3 polar(double thetaDeg, double phiDeg) {
    double t = thetaDeg * M_PI / 180, p = phiDeg * M_PI / 180;
    return {std::cos(p) * std::sin(t), std::sin(p) * std::sin(t), std::cos(t)};
}

TEST(KlemsBasis, StandardBasesHaveRadiancesPatchCounts) {
    EXPECT_EQ(KlemsBasis::standard("LBNL/Klems Full")->size(), 145);
    EXPECT_EQ(KlemsBasis::standard("LBNL/Klems Half")->size(), 77);
    EXPECT_EQ(KlemsBasis::standard("lbnl/klems quarter")->size(), 41);
    EXPECT_EQ(KlemsBasis::standard("LBNL/Shirley-Chiu"), nullptr);
}

// Patches worked out by hand from the Full basis's rings (0-5° ×1, 5-15° ×8, …, 75-90° ×12).
TEST(KlemsBasis, FullBasisIndicesByHand) {
    const KlemsBasis& b = *KlemsBasis::standard("LBNL/Klems Full");
    EXPECT_EQ(b.index({0, 0, 1}), 0);
    EXPECT_EQ(b.index(polar(4.9, 123)), 0);
    EXPECT_EQ(b.index(polar(5.001, 0)), 1);
    EXPECT_EQ(b.index(polar(10, 22)), 1);     // 22° < 22.5°: still the patch centred on 0°
    EXPECT_EQ(b.index(polar(10, 23)), 2);
    EXPECT_EQ(b.index(polar(10, 350)), 1);    // wraps round to the first patch
    EXPECT_EQ(b.index(polar(20, 90)), 9 + 4);  // ring 2 starts at 9, 16 patches of 22.5°
    EXPECT_EQ(b.index(polar(80, 180)), 133 + 6);
    EXPECT_EQ(b.index({0, 0, -1}), -1);
    // Projected solid angle of the polar patch: π sin²5°.
    EXPECT_NEAR(b.projectedSolidAngle(0), M_PI * std::pow(std::sin(5 * M_PI / 180), 2), 1e-12);
}

TEST(KlemsBasis, PatchesCoverTheHemisphereAndSamplesStayInside) {
    for (const char* name : {"LBNL/Klems Full", "LBNL/Klems Half", "LBNL/Klems Quarter"}) {
        const KlemsBasis& b = *KlemsBasis::standard(name);
        double sum = 0;
        for (int p = 0; p < b.size(); ++p) {
            sum += b.projectedSolidAngle(p);
            for (double u : {0.01, 0.5, 0.99})
                for (double v : {0.01, 0.5, 0.99}) EXPECT_EQ(b.index(b.direction(p, u, v)), p) << name << " " << p;
        }
        EXPECT_NEAR(sum, M_PI, 1e-9) << name;
    }
}

TEST(KlemsBasis, SidesMirrorThroughTheSurfaceAndTurnIncidentDirections) {
    const KlemsBasis& b = *KlemsBasis::standard("LBNL/Klems Full");
    dvec3 d = polar(10, 180);
    EXPECT_EQ((KlemsSide{true, false}.index(b, d)), 5);
    EXPECT_EQ((KlemsSide{true, true}.index(b, d)), 1);
    EXPECT_EQ((KlemsSide{false, false}.index(b, d)), -1);
    EXPECT_EQ((KlemsSide{false, false}.index(b, {d.x, d.y, -d.z})), 5);
    EXPECT_EQ((KlemsSide{false, true}.index(b, -d)), 5);
    dvec3 back = KlemsSide{false, true}.direction(b, 5, 0.5, 0.5);
    EXPECT_LT(back.z, 0);
    EXPECT_EQ((KlemsSide{false, true}.index(b, back)), 5);
}

}  // namespace
}  // namespace brume
