#include "light/light.h"

#include <gtest/gtest.h>

#include "geometry/polygon.h"
#include "world/scene_geometry.h"
#include "sampling/random.h"
#include "sampling/testing.h"

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

namespace {

using sampling::testing::DirectionOptions;

// 10⁵ draws in 20×40 cells: a density 11% off over a tenth of a source fails (more draws cost more: a source's
// density is a ray and a pdf at each point of the integrals).
const DirectionOptions kDraws{.draws = 100'000, .rings = 20, .sectors = 40};

// A source's draws from `eye` follow Light::pdf (chi-square, sampling/testing.h, counted in `grid`): the density of a
// direction is pdf() at the ray's first hit on the source, with that hit's distance and normal, as the integrator
// evaluates it where a sampled ray meets the source (0 where the ray misses it, and, for spotlights, outside their
// cone, whose draws are lost). Each draw's own pdf, distance and normal are those of its direction's hit: next-event
// estimation weighs the draw by the one, the sampled ray by the other (MIS).
void expectDrawsFollowPdf(const Light& light, const Surface& surface, const dvec3& eye, const DirectionOptions& grid) {
    SceneGeometry geometry({surface});
    auto firstHit = [&](const dvec3& d) { return geometry.intersect(Ray(eye, d)); };
    int disagreeing = 0;
    LightView view = light.view(eye);
    // (A draw on the source's very edge may miss it by rounding; draws that miss it in numbers fail the
    // chi-square. An area-sampled pdf is ∝ 1/cos of the source's normal with the ray: the cosine is allowed
    // 1e-9 of rounding, which is much at a curved source's silhouette.)
    auto sample = [&](double u, double v) -> std::optional<dvec3> {
        std::optional<LightSample> s = light.sample(view, u, v);
        if (!s) return std::nullopt;
        if (std::optional<SurfaceHit> hit = firstHit(s->dir)) {
            double cosine = std::abs(glm::dot(hit->normal, s->dir));
            disagreeing += !(std::abs(hit->t - s->distance) <= 1e-6 * s->distance &&
                             glm::length(hit->normal - s->normal) <= 1e-6 &&
                             std::abs(light.pdf(eye, s->dir, hit->t, hit->normal) - s->pdf) <= 1e-9 / cosine * s->pdf);
        }
        return s->dir;
    };
    auto density = [&](const dvec3& d) {
        std::optional<SurfaceHit> hit = firstHit(d);
        return hit && light.emitter().emitsToward(-d) ? light.pdf(eye, d, hit->t, hit->normal) : 0.0;
    };
    sampling::testing::expectSamplesFollowDensity(sample, density, grid);
    EXPECT_EQ(disagreeing, 0) << "draws whose pdf, distance or normal are not those of their direction's hit";
}

// The source seen from the points `eyes`, in cells over a cap about its outline.
void expectDrawsFollowPdf(const Surface& surface, const Emitter& emitter, std::initializer_list<dvec3> eyes) {
    Light light(surface, SurfaceId{0}, &emitter);
    for (const dvec3& eye : eyes) {
        SCOPED_TRACE(testing::Message() << "seen from " << eye.x << " " << eye.y << " " << eye.z);
        expectDrawsFollowPdf(light, surface, eye, sampling::testing::capAround(eye, light.outline(eye), kDraws));
    }
}

Emitter uniform() {
    Emitter e;
    e.radiance = Spectrum(1.f);
    return e;
}

}  // namespace

// Polygons sampled by solid angle (a rectangle, by one spherical rectangle, from near, far and just off its
// plane; a concave L, near and off its plane, and a triangle, by their spherical triangles) and by area (a 12-gon
// has more than 8 triangles; a rectangle far off looks smaller than 1e-4 sr).
TEST(Light, PolygonDrawsFollowItsPdf) {
    Emitter e = uniform();
    expectDrawsFollowPdf(polygonSurface({{-1, -1, 2}, {-1, 1, 2}, {1, 1, 2}, {1, -1, 2}}), e,
                         {dvec3(0.2, 0.1, 1.5), dvec3(3, -2, -30), dvec3(2.5, 0.3, 1.95)});
    expectDrawsFollowPdf(polygonSurface({{0, 0, 1}, {0, 2, 1}, {1, 2, 1}, {1, 1, 1}, {2, 1, 1}, {2, 0, 1}}), e,
                         {dvec3(0.5, 0.5, 0.5), dvec3(3, 0.5, 0.95)});
    expectDrawsFollowPdf(polygonSurface({{0, 0, 1}, {0, 1, 1.2}, {1, 0, 1}}), e, {dvec3(0.3, 0.2, 0.4)});
    std::vector<dvec3> twelve;
    for (int k = 0; k < 12; ++k)
        twelve.push_back({std::cos(-k * std::numbers::pi / 6), std::sin(-k * std::numbers::pi / 6), 2});
    expectDrawsFollowPdf(polygonSurface(twelve), e, {dvec3(0.3, 0, 1.2), dvec3(2, 1, 1.9)});
    expectDrawsFollowPdf(polygonSurface({{-0.1, -0.1, 2}, {-0.1, 0.1, 2}, {0.1, 0.1, 2}, {0.1, -0.1, 2}}), e,
                         {dvec3(1, 2, -20)});
}

// Spheres, sampled uniformly over the cone they fill, from near and far; discs and rings, and a cylinder from
// outside and a tube (facing inward) from inside, sampled by area.
TEST(Light, CurvedAndRoundDrawsFollowTheirPdf) {
    Emitter e = uniform();
    expectDrawsFollowPdf(Surface{0, Sphere{dvec3(0.5, 0.3, 2), 0.4, false}}, e, {dvec3(0.2, 0, 1.2), dvec3(5, 3, -10)});
    expectDrawsFollowPdf(Surface{0, Ring{dvec3(0, 0, 2), dvec3(0, 0, -1), 0, 0.5}}, e,
                         {dvec3(0.3, 0, 1), dvec3(2, 0, 1.9)});
    expectDrawsFollowPdf(Surface{0, Ring{dvec3(0, 0, 2), glm::normalize(dvec3(0.2, 0, -1)), 0.3, 0.6}}, e,
                         {dvec3(0, 0.2, 1.2)});
    expectDrawsFollowPdf(Surface{0, Cone{dvec3(0, 0, 1), dvec3(0, 0, 3), 0.3, 0.3, false}}, e, {dvec3(1, 0.5, 1.5)});
    Surface tube{0, Cone{dvec3(0, 0, 1), dvec3(0, 0, 3), 0.5, 0.5, true}};
    expectDrawsFollowPdf(Light(tube, SurfaceId{0}, &e), tube, dvec3(0.2, 0.1, 2.3), kDraws);  // all round the eye
}

// A spotlight's draws outside its cone are lost, where the density (the emitter's cut times pdf()) is 0.
TEST(Light, SpotlightDrawsOutsideItsConeAreLost) {
    Emitter spot = uniform();
    spot.kind = Emitter::Kind::Spotlight;
    spot.spotAxis = glm::normalize(dvec3(0.3, 0, -1));
    spot.spotCosHalf = std::cos(0.2);
    expectDrawsFollowPdf(polygonSurface({{-1, -1, 2}, {-1, 1, 2}, {1, 1, 2}, {1, -1, 2}}), spot, {dvec3(-0.2, 0.1, 1)});
}

// Sources at infinity: draws uniform over their cone (10°, and the sun's 0.53° in a cap about it), from anywhere.
TEST(Light, DistantDrawsFollowTheirPdf) {
    Emitter e = uniform();
    for (double angle : {10.0, 0.53}) {
        Light distant(dvec3(0.3, 0.2, 1), angle * std::numbers::pi / 180, &e, 0);
        sampling::testing::expectSamplesFollowDensity(
            [&](double u, double v) -> std::optional<dvec3> {
                auto s = distant.sample(distant.view(dvec3(0)), u, v);
                return s ? std::optional(s->dir) : std::nullopt;
            },
            [&](const dvec3& d) { return distant.pdf(dvec3(0), d, std::numeric_limits<double>::infinity(), -d); },
            sampling::testing::capAround(dvec3(0), distant.outline(dvec3(0)), kDraws));
    }
}
