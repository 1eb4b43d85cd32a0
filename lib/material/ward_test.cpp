// Ward's reflection and the Gaussian transmission lobe are sampled as the integrator samples them (a draw that
// leaves the lobe's side of the surface is lost), and their draws follow the densities it weighs them by.
#include "material/ward.h"

#include <gtest/gtest.h>

#include "sampling/testing.h"

using namespace brume;
using namespace brume::sampling::testing;

namespace {

const dvec3 kNormal = glm::normalize(dvec3(0.1, -0.2, 1));

// A direction at `degrees` from −normal … +normal (sign), turned about the normal by a fixed azimuth.
dvec3 atAngle(double degrees, double sign) {
    double t = degrees * std::numbers::pi / 180;
    Frame f(kNormal);
    return f.toWorld(dvec3(std::sin(t) * 0.6, std::sin(t) * 0.8, sign * std::cos(t)));
}

// 2×10⁵ draws in 20×40 cells over the cap of `reach` about `axis` (chi-square: 10% off over a tenth of the lobe
// fails). A lobe of roughness α reaches atan 4α (tan = α√(−ln u) exceeds 4α for e^{−16} of its draws), twice
// that for reflection about a half vector.
DirectionOptions aboutLobe(const dvec3& axis, double reach) {
    return {.draws = 200'000, .rings = 20, .sectors = 40, .axis = axis, .maxAngle = std::min(std::numbers::pi, reach)};
}

}  // namespace

// Rough and smooth lobes seen along the normal and at 80° from it, where part of the lobe falls below the
// horizon and its draws are lost.
TEST(Ward, ReflectionDrawsFollowItsDensity) {
    for (double alpha2 : {0.01, 0.04, 0.25})
        for (double view : {0.0, 80.0}) {
            dvec3 wo = atAngle(view, 1), mirror = 2 * glm::dot(wo, kNormal) * kNormal - wo;
            auto sample = [&](double u, double v) -> std::optional<dvec3> {
                dvec3 wi = sampleWard(wo, kNormal, alpha2, u, v);
                return glm::dot(wi, kNormal) > 0 ? std::optional(wi) : std::nullopt;
            };
            auto density = [&](const dvec3& wi) {
                return glm::dot(wi, kNormal) > 0 ? wardPdf(wo, wi, kNormal, alpha2) : 0.0;
            };
            SCOPED_TRACE(testing::Message() << "α² " << alpha2 << ", view at " << view << "°");
            expectSamplesFollowDensity(sample, density, aboutLobe(mirror, 2 * std::atan(4 * std::sqrt(alpha2))));
        }
}

// The same for light passing straight through at normal and at 80° incidence.
TEST(Ward, GaussianTransmissionDrawsFollowItsDensity) {
    for (double alpha2 : {0.01, 0.04, 0.25})
        for (double incidence : {0.0, 80.0}) {
            dvec3 through = atAngle(incidence, -1);
            auto sample = [&](double u, double v) -> std::optional<dvec3> {
                dvec3 wi = sampleGaussianTransmission(through, alpha2, u, v);
                return glm::dot(wi, kNormal) < 0 ? std::optional(wi) : std::nullopt;
            };
            auto density = [&](const dvec3& wi) {
                return glm::dot(wi, kNormal) < 0 ? gaussianTransmissionPdf(through, wi, alpha2) : 0.0;
            };
            SCOPED_TRACE(testing::Message() << "α² " << alpha2 << ", incidence " << incidence << "°");
            expectSamplesFollowDensity(sample, density, aboutLobe(through, std::atan(4 * std::sqrt(alpha2))));
        }
}
