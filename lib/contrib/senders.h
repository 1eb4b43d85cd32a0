// rfluxmtx's sender: the polygons and rings of a sender file taken as one surface (Radiance warns where they
// have several modifiers and takes them all), with the hemisphere basis its rays go out over, into the side its
// area-weighted normal points away from ("#@rfluxmtx h=… u=…": uniform, Tregenza's or Reinhart's patches,
// Klems'). Each of the basis's bins is one row of the matrix, the mean of -c rays: directions spread over the
// bin (a scrambled Sobol' sequence; as Radiance's, uniform in projected solid angle for h=u and Klems' patches,
// in altitude and azimuth for Reinhart's), origins uniform in area over the surfaces, a surface chosen in
// proportion to its area projected across the ray.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "contrib/flux_surfaces.h"
#include "geometry/shapes.h"
#include "material/klems_basis.h"
#include "sampling/polygon_points.h"

namespace brume {

class Sender {
public:
    // Throws Error: a file without polygons or rings, a source, no or an unknown h=, an up along the normal.
    explicit Sender(const std::string& path);

    int bins() const { return bins_; }
    int surfaces() const { return int(surfaces_.size()); }
    // Ray `index` of bin `bin` (origin, then unit direction), from samples seeded by `seed`.
    std::array<double, 6> ray(int bin, uint32_t index, uint64_t seed) const;
    // The unit direction of a ray of the bin for (u, v) uniform in [0, 1)²: into the side the normal points away
    // from, with the bin's density.
    dvec3 direction(int bin, double u, double v) const;
    // The sender's frame: its area-weighted unit normal, and ±(up × normal), normal × (up × normal).
    const dvec3& normal() const { return normal_; }
    const dvec3& u() const { return u_; }
    const dvec3& v() const { return v_; }

private:
    struct Surface {
        dvec3 normal;  // unit
        double area;
        std::unique_ptr<Polygon> polygon;  // a polygon's, with its points; else a ring
        PolygonPoints points;
        dvec3 centre;
        double inner = 0;  // a ring's inner radius
    };
    // A point on the surfaces for a ray along `dir`, for u, v uniform in [0, 1).
    dvec3 origin(const dvec3& dir, double u, double v) const;
    dvec3 local(const dvec3& d) const { return d.x * u_ + d.y * v_ + d.z * normal_; }
    static Surface surfaceOf(const FluxSurface& s);
    void setFrame(const FluxSettings& settings, const std::string& path);
    void setBasis(const FluxSettings& settings, const std::string& path);

    std::vector<Surface> surfaces_;
    dvec3 normal_{0}, u_, v_;  // the basis's frame: u = ±(up × normal), v = normal × (up × normal)
    char kind_ = 'u';          // 'u' uniform, 'r' Reinhart's (and Tregenza's) patches, 'k' Klems'
    int subdivisions_ = 1;     // Reinhart's MF
    const KlemsBasis* klems_ = nullptr;
    int bins_ = 1;
};

}  // namespace brume
