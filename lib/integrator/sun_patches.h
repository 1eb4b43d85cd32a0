// Sun patches: the sun through a window lands on a few square metres of floor and wall, and they light the
// rest of the room. A diffuse ray from elsewhere finds a patch rarely, and brings the whole sun when it
// does. So wherever the diffuse interreflection is path traced, as many samples aim at the patches as rays
// go out at random: each lands a point across the sunbeam through a portal (uniform over the beam's
// cross-section) where the beam first meets a surface, and connects to it. The two routes to a diffusely
// reflecting patch point are weighed by the power heuristic: the connection here, and the ray's, whose share
// next-event estimation at the patch applies (rayShare). Unbiased either way; -aP- turns it off with the
// portals. Sources that count: small distant ones (the sun, below kMaxAngle) shining through portals.
#pragma once
#include "cache/hemisphere_samples.h"
#include "integrator/hit_shading.h"
#include "integrator/light_sampler.h"
#include "integrator/shadow_rays.h"
#include "integrator/sky_portals.h"

namespace brume {

class SunPatches final : public SourceShares {
public:
    SunPatches(const RenderScene& scene, const HitShading& shading, const ShadowRays& shadowRays,
               const LightSampler& lights, bool enabled);

    bool active() const { return !beams_.empty(); }
    // Added to the radiance of `rays` cosine-distributed rays from x (facing n, leaving `surface`):
    // aimedCount(rays) connections to sunlit points per beam, each the point's reflected sunlight × its
    // multiple-importance weight × cosθ/(π·pdf), scaled to `rays` samples. `state`: the rays' (the volumes
    // they are in, their bounce). `aimed`, if given, receives each connection that brings light, with its
    // share of the irradiance.
    Spectrum sample(const dvec3& x, const dvec3& n, const SurfaceId& surface, int rays, const PathState& state,
                    PathContext& ctx, std::vector<AimedSample>* aimed = nullptr) const;
    double rayShare(const Light& light, const Scatterer& at, const SurfaceId& surface, const PathState& state,
                    PathContext& ctx) const override;

    // For tests. The point where the sunbeam of source `light` through the portals lands for (u, v) in the
    // unit square, and the density per unit area with which it is drawn at a point of a surface.
    std::optional<SurfaceHit> land(int light, double u, double v) const;
    double areaDensity(int light, const dvec3& point, const SurfaceId& surface, const dvec3& normal) const;

private:
    static constexpr double kMaxAngle = 0.05;  // rad: the sun's is 0.0093

    // The sunlight of one source through every portal it shines through.
    struct Beam {
        int light;
        dvec3 travel;                 // the direction the light travels in
        double crossSection;          // Σ portal area × |cos| to the light
        std::vector<double> cdf;      // per portal: cumulative share of the cross-section
    };
    const Beam* beamOf(int light) const;
    std::optional<SurfaceHit> land(const Beam& beam, double u, double v) const;
    // How many portals the beam crosses on its way to a point of `surface` (each could have brought it there).
    int portalsBefore(const Beam& beam, const dvec3& point, const SurfaceId& surface) const;
    double density(const Beam& beam, int portals, const dvec3& normal) const;
    bool isPortal(const SurfaceId& id) const;
    // What a connection from x (a ray that meets the sunlit point `at`, through glazing of transmission t,
    // cosX to x's normal) brings: the sunlight the point reflects back along it, if it only reflects diffusely,
    // × t × the connection's multiple-importance weight × cosθ/(π·pdf), of `perRay` connections per ray.
    std::optional<Spectrum> connected(const Beam& beam, const SurfaceHit& at, const Ray& connection, const Spectrum& t,
                                      double cosX, double perRay, const PathState& state, PathContext& ctx) const;

    const RenderScene& scene_;
    const HitShading& shading_;
    const ShadowRays& shadowRays_;
    const LightSampler& lights_;
    std::vector<Beam> beams_;
};

}  // namespace brume
