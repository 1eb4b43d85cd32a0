// The density of a smoke along one ray, as the ray meets it: pieces of the ray over which the density is a
// cubic in the distance (trilinear interpolation inside a cell between voxel centres, a constant inside an
// even majorant cell), from which the density at any t and its integral from the stretch's start to t are
// exact. What sampling distances by the true optical depth needs (DepthCollision), where a majorant's
// exponential would put its draws where the smoke is not.
#pragma once
#include <array>
#include <vector>

namespace brume {

class DensityProfile {
public:
    // The density over [a, b] is c[0] + c[1]·s + c[2]·s² + c[3]·s³, s = t − a.
    struct Piece {
        double a, b;
        std::array<double, 4> c;
        double before = 0;  // ∫ density over the pieces before this one
    };

    // A piece after those added so far (a ≥ the last piece's b); empty or zero pieces are dropped.
    void append(double a, double b, const std::array<double, 4>& c);
    void append(double a, double b, double density) { append(a, b, {density, 0, 0, 0}); }
    // All of `other`'s pieces after this one's.
    void append(const DensityProfile& other);

    // ∫ density dt from the first piece to t (0 before it, the total after the last).
    double integral(double t) const;
    // The same and the density at t, from one search for t's piece.
    struct Point {
        double integral, density;
    };
    Point at(double t) const;
    // The t where integral(t) reaches `integral` (in [0, total()]): the first piece's start for 0, the last's
    // end past the total.
    double inverse(double integral) const;
    double total() const { return pieces_.empty() ? 0 : pieces_.back().before + integralOf(pieces_.back(), pieces_.back().b); }
    // The density at t (0 outside the pieces, never negative).
    double density(double t) const;
    bool empty() const { return pieces_.empty(); }
    const std::vector<Piece>& pieces() const { return pieces_; }

    // w·this + v·other, over the union of their pieces' ends (two key frames of a smoke, blended in time; or
    // several smokes' extinctions, each its own K times its density).
    static DensityProfile sum(const DensityProfile& p, double w, const DensityProfile& q, double v);

private:
    static double integralOf(const Piece& p, double t);
    // The piece holding t, or the first after it; end() past the last.
    std::vector<Piece>::const_iterator pieceAt(double t) const;

    std::vector<Piece> pieces_;
};

}  // namespace brume
