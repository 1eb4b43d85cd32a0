// Writes the demo's flame: flame.vdb with the grids `density` (soot, kg/m³) and `temperature` (K) of a small
// pool fire's plume, an analytic model, not a fire simulation: a cone of hot gas 0.5 m across at its base on
// the floor, 1.2 m tall, hottest (1500 K, about a luminous hydrocarbon flame's soot) on its axis a fifth of
// the way up and cooling to the room's 293 K at its edge and tip; soot 2·10⁻⁴ kg/m³ where it is hottest, in
// proportion to the temperature rise (so K_m = 8700 m²/kg makes the core about 1.7 per metre: a flame one
// can see into). Voxels of 2 cm centred on (x, y) = (0, 0).
//     make_flame OUT.vdb
#include <openvdb/openvdb.h>

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_flame OUT.vdb\n");
        return 2;
    }
    openvdb::initialize();
    constexpr double kVoxel = 0.02, kRadius = 0.25, kHeight = 1.2, kAmbient = 293, kHottest = 1500, kSoot = 2e-4;
    auto density = openvdb::FloatGrid::create(0.0f), temperature = openvdb::FloatGrid::create(0.0f);
    for (auto* grid : {&density, &temperature}) {
        (*grid)->setTransform(openvdb::math::Transform::createLinearTransform(kVoxel));
        (*grid)->setGridClass(openvdb::GRID_FOG_VOLUME);
    }
    density->setName("density"), temperature->setName("temperature");
    auto soot = density->getAccessor();
    auto heat = temperature->getAccessor();
    const int across = int(std::ceil(kRadius / kVoxel)) + 1, up = int(std::ceil(kHeight / kVoxel));
    for (int k = 0; k <= up; ++k)
        for (int j = -across; j <= across; ++j)
            for (int i = -across; i <= across; ++i) {
                double x = i * kVoxel, y = j * kVoxel, z = k * kVoxel;
                double radius = kRadius * (1 - z / kHeight);  // the cone narrows to its tip
                double r = std::hypot(x, y);
                if (!(radius > 0) || r > radius) continue;
                // Hottest on the axis a fifth of the way up, cooling toward the edge and the tip.
                double u = z / kHeight;
                double rise = std::sqrt(1 - (r / radius) * (r / radius)) * std::min(1.0, 0.6 + 2 * u) *
                              std::min(1.0, 1.25 * (1 - u));
                if (rise <= 0) continue;
                openvdb::Coord c(i, j, k);
                heat.setValue(c, float(kAmbient + (kHottest - kAmbient) * rise));
                soot.setValue(c, float(kSoot * rise));
            }
    openvdb::io::File(argv[1]).write({density, temperature});
    return 0;
}
