#include "light/light.h"

#include <gtest/gtest.h>

#include "geometry/polygon.h"
#include "sampling/random.h"

using namespace brume;

namespace {

// ∫ cos dω over the source by plain Monte Carlo of its own sampling, for one receiver.
double sampledIrradiance(const Light& light, const dvec3& p, const dvec3& n, int samples = 1 << 18) {
    LightView view = light.view(p);
    double sum = 0;
    for (int i = 0; i < samples; ++i) {
        double u, v;
        sobol2D(uint32_t(i), 0x1234567890abcdefULL, u, v);
        auto s = light.sample(view, u, v);
        if (s) sum += std::max(0.0, glm::dot(n, s->dir)) / s->pdf;
    }
    return sum / samples;
}

Surface polygonSurface(std::vector<dvec3> v) {
    std::string why;
    Polygon p = *makePolygon(std::move(v), why);
    p.triangles = triangulate(p);
    return Surface{0, p};
}

}  // namespace

// The closed forms agree with the sources' own sampling (0.1%: 2^18 stratified samples).
TEST(Light, ClosedFormIrradianceMatchesSampling) {
    Emitter e;
    e.radiance = Spectrum(1.f);
    // A square facing down above the receiver, one crossing its horizon, a concave L.
    std::vector<Surface> shapes{
        polygonSurface({{-1, -1, 2}, {-1, 1, 2}, {1, 1, 2}, {1, -1, 2}}),
        polygonSurface({{2, -1, -1}, {2, -1, 1}, {2, 1, 1}, {2, 1, -1}}),
        polygonSurface({{0, 0, 1}, {0, 2, 1}, {1, 2, 1}, {1, 1, 1}, {2, 1, 1}, {2, 0, 1}}),
        Surface{0, Sphere{dvec3(0.5, 0.3, 2), 0.4, false}},
    };
    for (const Surface& shape : shapes) {
        Light light(shape, SurfaceId{0}, &e);
        for (dvec3 n : {dvec3(0, 0, 1), glm::normalize(dvec3(1, 0, 1)), glm::normalize(dvec3(0.3, -0.5, 1))}) {
            double closed = light.unoccludedIrradiance(dvec3(0), n);
            if (closed < 0) continue;
            double sampled = sampledIrradiance(light, dvec3(0), n);
            EXPECT_NEAR(closed, sampled, 1e-3 * sampled + 1e-9) << "normal " << n.x << " " << n.y << " " << n.z;
        }
    }
    Light sun(dvec3(0.3, 0.2, 1), 0.0093, &e, 0);
    double closed = sun.unoccludedIrradiance(dvec3(0), dvec3(0, 0, 1));
    EXPECT_NEAR(closed, sampledIrradiance(sun, dvec3(0), dvec3(0, 0, 1)), 1e-3 * closed);
}
