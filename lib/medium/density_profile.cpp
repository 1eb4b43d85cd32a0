#include "medium/density_profile.h"

#include <algorithm>
#include <set>

namespace brume {

namespace {

// The cubic c(s) re-expanded about s = δ (Taylor's shift): c(δ + s) in powers of s.
std::array<double, 4> shifted(const std::array<double, 4>& c, double delta) {
    return {c[0] + delta * (c[1] + delta * (c[2] + delta * c[3])), c[1] + delta * (2 * c[2] + 3 * delta * c[3]),
            c[2] + 3 * delta * c[3], c[3]};
}

}  // namespace

void DensityProfile::append(double a, double b, const std::array<double, 4>& c) {
    if (!(b > a) || std::all_of(c.begin(), c.end(), [](double x) { return x == 0; })) return;
    pieces_.push_back({a, b, c, total()});
}

void DensityProfile::append(const DensityProfile& other) {
    for (const Piece& p : other.pieces_) append(p.a, p.b, p.c);
}

double DensityProfile::integralOf(const Piece& p, double t) {
    const double s = std::clamp(t - p.a, 0.0, p.b - p.a);
    return s * (p.c[0] + s * (p.c[1] / 2 + s * (p.c[2] / 3 + s * p.c[3] / 4)));
}

std::vector<DensityProfile::Piece>::const_iterator DensityProfile::pieceAt(double t) const {
    return std::lower_bound(pieces_.begin(), pieces_.end(), t, [](const Piece& p, double x) { return p.b < x; });
}

double DensityProfile::integral(double t) const { return at(t).integral; }

double DensityProfile::density(double t) const { return at(t).density; }

DensityProfile::Point DensityProfile::at(double t) const {
    auto p = pieceAt(t);
    if (p == pieces_.end()) return {total(), 0};
    if (t < p->a) return {p->before, 0};
    const double s = t - p->a;
    return {p->before + integralOf(*p, t), std::max(0.0, p->c[0] + s * (p->c[1] + s * (p->c[2] + s * p->c[3])))};
}

double DensityProfile::inverse(double integral) const {
    if (pieces_.empty()) return 0;
    // The last piece that starts at or below the integral sought.
    auto p = std::upper_bound(pieces_.begin(), pieces_.end(), integral,
                              [](double x, const Piece& q) { return x < q.before; });
    p = p == pieces_.begin() ? p : std::prev(p);
    const double target = integral - p->before;
    double lo = 0, hi = p->b - p->a;
    if (!(target < integralOf(*p, p->b))) return p->b;
    if (!(target > 0)) return p->a;
    // Newton's steps on the piece's integral (its derivative the density), bisection where they stray.
    double s = hi * target / integralOf(*p, p->b);
    for (int i = 0; i < 60 && hi - lo > 1e-13 * (1 + std::abs(p->a)); ++i) {
        double f = integralOf(*p, p->a + s) - target;
        if (std::abs(f) <= 1e-14 * (1 + integral)) break;
        (f < 0 ? lo : hi) = s;
        double rho = p->c[0] + s * (p->c[1] + s * (p->c[2] + s * p->c[3]));
        double next = rho > 0 ? s - f / rho : -1;
        s = next > lo && next < hi ? next : 0.5 * (lo + hi);
    }
    return p->a + s;
}

DensityProfile DensityProfile::sum(const DensityProfile& p, double w, const DensityProfile& q, double v) {
    std::set<double> ends;
    for (const DensityProfile* x : {&p, &q})
        for (const Piece& piece : x->pieces_) ends.insert({piece.a, piece.b});
    DensityProfile out;
    auto i = p.pieces_.begin(), j = q.pieces_.begin();
    for (auto from = ends.begin(), to = std::next(from); from != ends.end() && to != ends.end(); from = to++) {
        const double a = *from, b = *to;
        while (i != p.pieces_.end() && i->b <= a) ++i;
        while (j != q.pieces_.end() && j->b <= a) ++j;
        std::array<double, 4> c{0, 0, 0, 0};
        auto add = [&](const Piece& piece, double weight) {
            if (!(piece.a <= a)) return;  // [a, b] lies in a gap before this piece
            std::array<double, 4> s = shifted(piece.c, a - piece.a);
            for (int k = 0; k < 4; ++k) c[k] += weight * s[k];
        };
        if (i != p.pieces_.end()) add(*i, w);
        if (j != q.pieces_.end()) add(*j, v);
        out.append(a, b, c);
    }
    return out;
}

}  // namespace brume
