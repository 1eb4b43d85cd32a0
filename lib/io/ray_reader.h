// Rays on rtrace's standard input: "xorg yorg zorg xdir ydir zdir", as ASCII words (-fa), native floats
// (-ff) or native doubles (-fd).
#pragma once
#include <array>
#include <istream>

namespace brume {

class RayReader {
public:
    RayReader(std::istream& in, char format) : in_(in), format_(format) {}
    // The next ray; false at the end of input. As in Radiance, ASCII input ends at the first word that
    // is not a number; a partial ray at the end is reported through partial().
    bool next(std::array<double, 6>& ray);
    bool partial() const { return partial_; }

private:
    bool word(double& v);
    std::istream& in_;
    char format_;
    bool partial_ = false;
};

}  // namespace brume
