// An FDS case's building, from its input: the solids (OBST boxes less the HOLEs that cut them), the walls of the
// computational domain (the faces of the MESH boxes that no other mesh touches, less the OPEN VENTs on them:
// FDS closes a domain with inert walls), the other VENTs (a fire's burner) as patches, and the SURF each is
// made of, with its colour (COLOR by name, or RGB).
#pragma once
#include <array>
#include <map>
#include <string>
#include <vector>

#include "fds/fds_input.h"
#include "geometry/bounds.h"

namespace brume {

struct CaseSolid {
    Bounds3 box;
    std::string surf;  // SURF_ID (FDS's default surface "INERT" where none is given)
    std::string id;    // the OBST's ID, or ""
};

// A rectangle on the plane x[axis] = at, over [lo, hi] in the other two axes (in increasing order), facing
// +axis (`facing` 1) or −axis (−1).
struct CaseRectangle {
    int axis = 0;
    double at = 0;
    std::array<double, 2> lo{}, hi{};
    int facing = 1;
    std::string surf;
    std::string id;
    // Its corners, counter-clockwise seen from the side it faces (Radiance's order for a polygon's front).
    std::array<dvec3, 4> corners() const;
};

// The face of `box` on its lower (`high` false) or upper side along `axis`, facing out of the box (`outward`) or
// into it.
CaseRectangle boxFace(const Bounds3& box, int axis, bool high, bool outward, const std::string& surf,
                      const std::string& id);

struct CaseSurface {
    std::array<double, 3> rgb{0.5, 0.5, 0.5};  // 0-1, as FDS's display colour (sRGB)
    bool coloured = false;                     // COLOR or RGB given (else the default grey)
};

struct CaseGeometry {
    std::vector<Bounds3> meshes;
    std::vector<CaseSolid> solids;
    std::vector<CaseRectangle> walls;   // of the domain, facing into it
    std::vector<CaseRectangle> vents;   // VENTs that are not OPEN, facing into the domain
    std::vector<CaseRectangle> openings;  // OPEN VENTs on the domain's walls
    std::map<std::string, CaseSurface> surfaces;  // by SURF ID, "INERT" and "OPEN" included
    std::vector<std::string> warnings;  // "file:line: …": colours unknown, vents not on a plane, …

    bool inside(const dvec3& p) const;     // in a mesh's box
    bool inSolid(const dvec3& p) const;    // in a solid's box (closed)
};

// From the groups of an .fds file. Throws Error "file:line: …" where a MESH, OBST, HOLE or VENT lacks XB or
// has an inverted one, or there is no MESH.
CaseGeometry caseGeometry(const std::vector<FdsGroup>& groups);

// The sRGB colour of one of FDS's colour names ('DIM GRAY', 'RED', …: the X11 names it takes), or none.
std::optional<std::array<double, 3>> fdsColour(const std::string& name);

}  // namespace brume
