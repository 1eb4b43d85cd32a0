// Where a smoke's data reach: the boxes of the domain a simulation computed (an FDS case's meshes) and the boxes
// of it its files give values for. A line through the domain outside every box with data crosses smoke no
// one knows, not clear air: studies measure how much of a line that is, and say so.
//
// Carried by the grids' metadata, as fds2vdb writes it: "brume:domain" and "brume:data", each a list of boxes
// "x0 y0 z0 x1 y1 z1" separated by ";" (world metres), and "brume:data_note", what each box with data holds.
// Grids without them (an artist's smoke, any grid not from a simulation) claim no domain: nothing is unknown.
#pragma once
#include <string>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/ray.h"

namespace brume {

class DataCoverage {
public:
    DataCoverage() = default;  // no domain
    // Error ("brume:domain: …", "brume:data: …") where a box is inverted or not finite. Data need not fill the
    // domain, nor stay in it.
    DataCoverage(std::vector<Bounds3> domain, std::vector<Bounds3> data, std::string note = "");
    // From the metadata's texts (either may be empty; Error "key: …" where one is malformed).
    static DataCoverage parse(const std::string& domain, const std::string& data, const std::string& note = "");
    static std::string format(const std::vector<Bounds3>& boxes);

    const std::vector<Bounds3>& domain() const { return domain_; }
    const std::vector<Bounds3>& data() const { return data_; }
    const std::string& note() const { return note_; }
    // Whether some of the domain has no data (a point of a domain box in no data box).
    bool incomplete() const { return incomplete_; }
    // The length of [t0, t1] along the ray inside the domain and outside every box with data.
    double uncoveredLength(const Ray& ray, double t0, double t1) const;

private:
    std::vector<Bounds3> domain_, data_;
    std::string note_;
    bool incomplete_ = false;
};

}  // namespace brume
