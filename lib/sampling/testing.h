// For unit tests of samplers: Pearson's chi-square test of goodness of fit between the draws of a sampler and
// the density it reports, as Mitsuba 3 tests its samplers (its chi2 module). The draws are counted in cells
// (directions: equal solid angles, rows of cos θ by columns of φ about an axis; distances: equal steps), the
// density is integrated over each cell, and the counts are compared with N times those integrals. Draws that
// give no sample, or fall off the grid, are counted in one more cell, the lost mass, expected N(1 − ∫ density):
// so a density that claims mass its sampler drops (or the reverse) fails too.
//
// What a test can see: a density off by a fraction ε over a share f of the draws adds about N f ε² to a statistic
// that spreads by √(2k) for k degrees of freedom, and a test at this suite's significance fails beyond about
// 4√(2k). So 2×10⁵ draws in 20×40 cells (k ≈ 800) see a density 10% off over a tenth of the draws; 10⁶ in
// 50×100, 6%. The cells must resolve the density for its integrals to be right: a part of it thinner than a
// hundredth of a cell (a source seen almost edge on) may escape them; look at it through a cap (capAround).
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "sampling/random.h"
#include "sampling/warp.h"

namespace brume::sampling::testing {

// A draw for (u, v) uniform in [0, 1)²: a unit direction, or nothing (that mass is lost).
using DirectionSampler = std::function<std::optional<dvec3>(double u, double v)>;
// The density per steradian the sampler reports for a direction.
using DirectionDensity = std::function<double(const dvec3&)>;
// The same for distances along a line: a draw for u uniform in [0, 1), and the density per unit length.
using DistanceSampler = std::function<std::optional<double>(double u)>;
using DistanceDensity = std::function<double(double)>;

struct DirectionOptions {
    int draws = 1'000'000;
    // Cells: `rings` equal steps of cos θ by `sectors` of φ about `axis`, over the directions within
    // `maxAngle` of it (a small source is looked at closely by a cap about it; draws outside count as lost).
    int rings = 50, sectors = 100;
    dvec3 axis{0, 0, 1};
    double maxAngle = std::numbers::pi;
    uint64_t seed = 1;
};

// `o` with its grid over the cap about the mean direction from `eye` to `points` that holds them all, with a
// tenth of its angle to spare: a close look at a small region (a source's outline). Caps wider than a
// hemisphere become the whole sphere.
inline DirectionOptions capAround(const dvec3& eye, const std::vector<dvec3>& points, DirectionOptions o = {}) {
    dvec3 mean(0);
    for (const dvec3& p : points) mean += glm::normalize(p - eye);
    o.axis = glm::normalize(mean);
    double widest = 0;
    for (const dvec3& p : points)
        widest = std::max(widest, std::acos(std::clamp(glm::dot(glm::normalize(p - eye), o.axis), -1.0, 1.0)));
    o.maxAngle = widest < std::numbers::pi / 2 ? 1.1 * widest : std::numbers::pi;
    return o;
}

struct DistanceOptions {
    double lo, hi;  // the cells cover [lo, hi]; draws outside count as lost
    int bins = 100;
    int draws = 200'000;
    uint64_t seed = 1;
};

struct ChiSquareResult {
    bool accepted = false;
    double statistic = 0, pValue = 0, significance = 0;
    int degreesOfFreedom = 0;
    double densityIntegral = 0;  // ∫ density over the cells: ≤ 1, and 1 when the sampler loses no mass
    double sampledFraction = 0;  // of the draws, those that gave a sample on the grid
    std::string report;          // the figures above and, on failure, the worst cells
};

// The regularised upper incomplete gamma function Q(a, x) = Γ(a, x)/Γ(a), a > 0, x ≥ 0, as Numerical Recipes
// (Press et al., 3rd ed., §6.2) computes it: for x < a + 1 the series
//     P(a, x) = e^{−x} x^a / Γ(a) · Σₙ xⁿ / (a (a + 1) ⋯ (a + n)),  Q = 1 − P,
// else the continued fraction
//     Q(a, x) = e^{−x} x^a / Γ(a) · 1/(x + 1 − a − 1·(1 − a)/(x + 3 − a − 2·(2 − a)/(x + 5 − a − ⋯)))
// evaluated by the modified Lentz method. Both converge in O(√a) terms, a few hundred at the degrees of freedom
// used here. The chi-square p-value with k degrees of freedom of a statistic χ² is Q(k/2, χ²/2).
inline double upperGammaQ(double a, double x) {
    if (x <= 0) return 1;
    const double prefactor = std::exp(-x + a * std::log(x) - std::lgamma(a)), eps = 1e-15, tiny = 1e-300;
    if (x < a + 1) {
        double term = 1 / a, sum = term;
        for (double ap = a; std::abs(term) >= std::abs(sum) * eps;) sum += term *= x / ++ap;
        return std::max(0.0, 1 - sum * prefactor);
    }
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        d = std::abs(d) < tiny ? tiny : d;
        c = b + an / c;
        c = std::abs(c) < tiny ? tiny : c;
        d = 1 / d;
        h *= d * c;
        if (std::abs(d * c - 1) <= eps) break;
    }
    return prefactor * h;
}

// The significance of each test: 1% for the whole suite. Each chi-square test rejects a correct sampler with
// probability α', so n of them reject at least one with 1 − (1 − α')ⁿ; Šidák's correction (as Mitsuba's)
// makes that α = 0.01: α' = 1 − (1 − α)^{1/n}. kTestsInSuite bounds n, the number of chiSquare calls the
// suite makes (99 today: raise it when adding more); a bound too high only makes each test a little
// less sensitive (α' = 1.0e-4 for n = 100).
constexpr double kSuiteSignificance = 0.01;
constexpr int kTestsInSuite = 100;
inline double testSignificance() { return 1 - std::pow(1 - kSuiteSignificance, 1.0 / kTestsInSuite); }

namespace detail {

struct Box {
    double x0, x1, y0, y1;
};

// Cells over a rectangle of parameters, `rows` steps of x by `columns` of y: (cos θ, φ) for directions, whose
// solid angle is dcosθ dφ; (t, nothing) for distances.
struct Grid {
    double x0, x1;
    int rows;
    double y0, y1;
    int columns;
    std::function<std::string(int row, int column)> describe;  // a cell, for the report
    int cells() const { return rows * columns; }
};

// ∫∫ f over a cell by Simpson's rule on 3×3 points, each box refined into quarters until it and the sum of its
// quarters agree within the tolerance (adaptive Simpson, Lyness 1969), the quarters' points found among the
// box's 5×5. Simpson's points take in the boxes' edges, so that a jump anywhere in a box changes the sum of its
// quarters and is refined (Gauss's points, all inside, miss jumps near the edges). Points on the cell's edges
// are moved a ten-millionth of the cell inside it (as Mitsuba's points are), so that a density's jump along a
// cell edge (a hemisphere's horizon about the normal, a cone's rim) is not evaluated right on it, on whichever
// side rounding gives.
class CellIntegral {
public:
    CellIntegral(const std::function<double(double, double)>& f, const Box& cell) : f_(f), cell_(cell) {}

    struct Result {
        double value = 0;
        double error = 0;  // the sum of what the last refinement of each part changed: about the error's size
        bool converged = true;
    };
    // ∫∫ f over the cell to within tolerance(a first estimate of it).
    Result operator()(const std::function<double(double)>& tolerance) const {
        Result r;
        Points f = points(cell_, nullptr, 0, 0);
        refine(cell_, f, tolerance(std::max(simpson(f, 0, 0, 2), quartersMean(f)) * area(cell_)), kMaxDepth, r);
        return r;
    }
    // ∫∫ f over the cell by the midpoint rule on n × n points: no part of the density larger than 1/n of the
    // cell escapes it, however thin.
    double midpoints(int n) const {
        double sum = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                sum += f_(cell_.x0 + (i + 0.5) * (cell_.x1 - cell_.x0) / n,
                          cell_.y0 + (j + 0.5) * (cell_.y1 - cell_.y0) / n);
        return sum * area(cell_) / (n * n);
    }

private:
    static constexpr int kMaxDepth = 8;
    using Points = std::array<std::array<double, 5>, 5>;  // f at a box's 5×5 points (quarter steps)

    // f at box b's points; those of `parent` (if any) reused: b is its quarter (qi, qj).
    Points points(const Box& b, const Points* parent, int qi, int qj) const {
        const double insetX = 1e-7 * (cell_.x1 - cell_.x0), insetY = 1e-7 * (cell_.y1 - cell_.y0);
        Points f;
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j) {
                if (parent && i % 2 == 0 && j % 2 == 0) {
                    f[size_t(i)][size_t(j)] = (*parent)[size_t(2 * qi + i / 2)][size_t(2 * qj + j / 2)];
                    continue;
                }
                double x = std::clamp(b.x0 + i * (b.x1 - b.x0) / 4, cell_.x0 + insetX, cell_.x1 - insetX);
                double y = std::clamp(b.y0 + j * (b.y1 - b.y0) / 4, cell_.y0 + insetY, cell_.y1 - insetY);
                f[size_t(i)][size_t(j)] = f_(x, y);
            }
        return f;
    }
    static double area(const Box& b) { return (b.x1 - b.x0) * (b.y1 - b.y0); }
    // The mean of f by Simpson's rule on the 3×3 points (i0 + a·step, j0 + b·step).
    static double simpson(const Points& f, int i0, int j0, int step) {
        constexpr double weight[3] = {1, 4, 1};
        double sum = 0;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) sum += weight[a] * weight[b] * f[size_t(i0 + a * step)][size_t(j0 + b * step)];
        return sum / 36;
    }
    static double quartersMean(const Points& f) {
        return (simpson(f, 0, 0, 1) + simpson(f, 2, 0, 1) + simpson(f, 0, 2, 1) + simpson(f, 2, 2, 1)) / 4;
    }
    // Adds ∫∫ f over b to r. Each quarter is refined to half the tolerance: the tolerance scales as the square
    // root of the expected count (see chiSquare), and a quarter expects a quarter of it. A cell is cut into
    // quarters at least once: what refining changes is the sum of what each jump in the box changes, and two
    // jumps in a cell (the edges of two pieces of a density, of a source's two sides) may cancel in it.
    void refine(const Box& b, const Points& f, double tolerance, int depth, Result& r) const {
        double whole = simpson(f, 0, 0, 2) * area(b), quarters = quartersMean(f) * area(b);
        double change = std::abs(quarters - whole);
        if (depth < kMaxDepth && (change <= tolerance || depth == 0)) {
            r.value += quarters, r.error += change;
            r.converged = r.converged && change <= tolerance;
            return;
        }
        double xm = 0.5 * (b.x0 + b.x1), ym = 0.5 * (b.y0 + b.y1);
        const Box quarter[2][2] = {{{b.x0, xm, b.y0, ym}, {b.x0, xm, ym, b.y1}},
                                   {{xm, b.x1, b.y0, ym}, {xm, b.x1, ym, b.y1}}};
        for (int qi = 0; qi < 2; ++qi)
            for (int qj = 0; qj < 2; ++qj)
                refine(quarter[qi][qj], points(quarter[qi][qj], &f, qi, qj), tolerance / 2, depth - 1, r);
    }
    const std::function<double(double, double)>& f_;
    Box cell_;
};

struct Cell {
    double observed, expected;
    int index;  // in the grid; −1 for the lost mass
};

inline std::string format(const char* pattern, auto... values) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, pattern, values...);
    return buffer;
}

// The cells whose counts stray furthest from their expectation, worst first.
inline std::string worstCells(std::vector<Cell> cells, const Grid& grid) {
    auto misfit = [](const Cell& c) {
        if (c.expected > 0) return (c.observed - c.expected) / std::sqrt(c.expected);
        return c.observed > 0 ? std::numeric_limits<double>::infinity() : 0.0;
    };
    std::sort(cells.begin(), cells.end(),
              [&](const Cell& a, const Cell& b) { return std::abs(misfit(a)) > std::abs(misfit(b)); });
    std::string out = "worst cells (observed, expected, (observed − expected)/√expected):\n";
    for (size_t i = 0; i < std::min<size_t>(8, cells.size()); ++i) {
        const Cell& c = cells[i];
        std::string where = c.index < 0 ? "lost (no sample, or off the grid)"
                                        : grid.describe(c.index / grid.columns, c.index % grid.columns);
        out += format("  %-40s %10.0f %12.2f %+8.1f\n", where.c_str(), c.observed, c.expected, misfit(c));
    }
    return out;
}

// Pearson's statistic over cells merged in increasing order of expected count until each group expects at
// least 5 (Mitsuba's pooling: the chi-square distribution of the statistic holds only for such counts).
inline void pearson(std::vector<Cell> cells, ChiSquareResult& r) {
    std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.expected < b.expected; });
    double observed = 0, expected = 0;
    int groups = 0;
    for (const Cell& c : cells) {
        observed += c.observed, expected += c.expected;
        if (expected < 5) continue;
        r.statistic += (observed - expected) * (observed - expected) / expected;
        ++groups, observed = expected = 0;
    }
    if (expected > 0) r.statistic += (observed - expected) * (observed - expected) / expected, ++groups;
    r.degreesOfFreedom = groups - 1;
}

// The test itself, given the draws' counts per cell (and those lost) and the density over the grid.
inline ChiSquareResult chiSquare(const Grid& grid, const std::vector<double>& counts, double lost, int draws,
                                 int badDraws, const std::function<double(double, double)>& density) {
    ChiSquareResult r;
    r.significance = testSignificance();
    double dx = (grid.x1 - grid.x0) / grid.rows, dy = (grid.y1 - grid.y0) / grid.columns;
    std::vector<Cell> cells;
    int unconverged = 0, impossible = 0;
    double integrationError = 0;
    auto cell = [&](int index) {
        double x0 = grid.x0 + index / grid.columns * dx, y0 = grid.y0 + index % grid.columns * dy;
        return CellIntegral(density, Box{x0, x0 + dx, y0, y0 + dy});
    };
    for (int index = 0; index < grid.cells(); ++index) {
        // Integration error at most a tenth of the counting noise √(N p) (with p at least 1/N): it adds at most
        // 1% to the cell's share of the statistic.
        CellIntegral::Result p =
            cell(index)([&](double p) { return 0.1 * std::sqrt(std::max(p, 1.0 / draws) / draws); });
        unconverged += !p.converged;
        integrationError += p.error;
        cells.push_back({counts[size_t(index)], draws * p.value, index});
    }
    // Adaptive quadrature misses a thin part of the density (a source seen almost edge on) that falls between its
    // points at two levels in a row. The cells whose counts stray from their integrals by more than 3σ (the 32
    // that stray most: a density wrong all over needs no more) are integrated again on 128×128 midpoints before
    // they are judged.
    auto stray = [](const Cell& c) { return std::abs(c.observed - c.expected) / (std::sqrt(c.expected) + 1); };
    std::vector<Cell*> worst;
    for (Cell& c : cells)
        if (std::abs(c.observed - c.expected) > 3 * std::sqrt(c.expected) + 3) worst.push_back(&c);
    std::sort(worst.begin(), worst.end(), [&](const Cell* a, const Cell* b) { return stray(*a) > stray(*b); });
    for (size_t k = 0; k < std::min<size_t>(32, worst.size()); ++k)
        worst[k]->expected = draws * cell(worst[k]->index).midpoints(128);
    for (const Cell& c : cells) {
        r.densityIntegral += c.expected / draws;
        impossible += c.expected <= 0 && c.observed > 0;
    }
    // The lost mass's expected count is N(1 − ∫ density), known only to within the sum of the cells' integration
    // errors, which may be far more than its counting noise when little is lost: within that margin it is taken
    // as near the count as it allows (the statistic's least over what the integration leaves unknown).
    double lostExpected = draws * (1 - r.densityIntegral), margin = draws * integrationError;
    cells.push_back({lost, std::max(0.0, std::clamp(lost, lostExpected - margin, lostExpected + margin)), -1});
    r.sampledFraction = 1 - lost / draws;
    pearson(cells, r);
    r.pValue = r.degreesOfFreedom > 0 ? upperGammaQ(r.degreesOfFreedom / 2.0, r.statistic / 2) : 0;
    r.accepted = badDraws == 0 && r.degreesOfFreedom > 0 && r.pValue >= r.significance;
    r.report = format("chi-square %.1f, %d degrees of freedom: p-value %.3g against significance %.3g: %s\n",
                      r.statistic, r.degreesOfFreedom, r.pValue, r.significance, r.accepted ? "accepted" : "REJECTED");
    r.report += format("density integrates to %.6f ± %.1g over the grid; %.6f of %d draws gave a sample on it\n",
                       r.densityIntegral, integrationError, r.sampledFraction, draws);
    if (badDraws) r.report += format("%d draws were not finite unit vectors (or not finite distances)\n", badDraws);
    // Not a failure by itself: a cell the density's support only grazes may integrate to 0 (its expected count
    // below the integration's tolerance) and still get a draw. Many draws there fail the statistic.
    if (impossible) r.report += format("%d cells hold draws where the density integrates to 0\n", impossible);
    if (unconverged)
        r.report += format("%d cells' integrals did not converge (their expected counts may be off)\n", unconverged);
    if (!r.accepted) r.report += worstCells(cells, grid);
    return r;
}

}  // namespace detail

inline ChiSquareResult chiSquare(const DirectionSampler& sample, const DirectionDensity& density,
                                 const DirectionOptions& o = {}) {
    const Frame frame(glm::normalize(o.axis));
    const double zMin = std::cos(o.maxAngle), twoPi = 2 * std::numbers::pi;
    auto degrees = [](double radians) { return radians * 180 / std::numbers::pi; };
    detail::Grid grid{zMin, 1, o.rings, 0, twoPi, o.sectors, [&](int ring, int sector) {
                          double z0 = zMin + (1 - zMin) * ring / o.rings, z1 = zMin + (1 - zMin) * (ring + 1) / o.rings;
                          return detail::format("θ %.4g–%.4g°, φ %.4g–%.4g°", degrees(std::acos(z1)),
                                                degrees(std::acos(z0)), 360.0 * sector / o.sectors,
                                                360.0 * (sector + 1) / o.sectors);
                      }};
    std::vector<double> counts(size_t(grid.cells()), 0);
    double lost = 0;
    int bad = 0;
    Random random(o.seed);
    for (int k = 0; k < o.draws; ++k) {
        double u = random.uniform(), v = random.uniform();
        std::optional<dvec3> d = sample(u, v);
        if (d && !(std::abs(glm::length(*d) - 1) < 1e-6)) ++bad, d.reset();
        double z = d ? glm::dot(*d, frame.n) : 0;
        if (!d || z < zMin) {
            ++lost;
            continue;
        }
        double phi = std::atan2(glm::dot(*d, frame.t), glm::dot(*d, frame.s));
        int ring = std::min(o.rings - 1, int((z - zMin) / (1 - zMin) * o.rings));
        int sector = std::min(o.sectors - 1, int((phi < 0 ? phi + twoPi : phi) / twoPi * o.sectors));
        ++counts[size_t(ring * o.sectors + sector)];
    }
    return detail::chiSquare(grid, counts, lost, o.draws, bad, [&](double z, double phi) {
        double s = std::sqrt(std::max(0.0, 1 - z * z));
        return density(frame.toWorld(dvec3(s * std::cos(phi), s * std::sin(phi), z)));
    });
}

inline ChiSquareResult chiSquare(const DistanceSampler& sample, const DistanceDensity& density,
                                 const DistanceOptions& o) {
    detail::Grid grid{o.lo, o.hi, o.bins, 0, 1, 1, [&](int bin, int) {
                          double w = (o.hi - o.lo) / o.bins;
                          return detail::format("t %.6g–%.6g", o.lo + bin * w, o.lo + (bin + 1) * w);
                      }};
    std::vector<double> counts(size_t(o.bins), 0);
    double lost = 0;
    int bad = 0;
    Random random(o.seed);
    for (int k = 0; k < o.draws; ++k) {
        std::optional<double> t = sample(random.uniform());
        if (t && !std::isfinite(*t)) ++bad, t.reset();
        if (!t || *t < o.lo || *t > o.hi) {
            ++lost;
            continue;
        }
        ++counts[size_t(std::min(o.bins - 1, int((*t - o.lo) / (o.hi - o.lo) * o.bins)))];
    }
    return detail::chiSquare(grid, counts, lost, o.draws, bad, [&](double t, double) { return density(t); });
}

// The gtest checks: draws follow the density, else the report says where they do not.
inline void expectSamplesFollowDensity(const DirectionSampler& sample, const DirectionDensity& density,
                                       const DirectionOptions& options = {}) {
    ChiSquareResult r = chiSquare(sample, density, options);
    EXPECT_TRUE(r.accepted) << r.report;
}
inline void expectSamplesFollowDensity(const DistanceSampler& sample, const DistanceDensity& density,
                                       const DistanceOptions& options) {
    ChiSquareResult r = chiSquare(sample, density, options);
    EXPECT_TRUE(r.accepted) << r.report;
}

// A draw with the density it carries (a lobe's or a phase function's sample: its direction and pdf).
struct WeighedDraw {
    dvec3 dir;
    double pdf;
};
using WeighedSampler = std::function<std::optional<WeighedDraw>(double u, double v)>;

// The draws follow `density`, and each draw's own pdf is `density` of its direction (within 1e-9): an
// integrator weighs a drawn ray by the one and a light sample by the other (MIS), so either off biases the
// light it finds.
inline void expectDrawsFollowTheirDensity(const WeighedSampler& sample, const DirectionDensity& density,
                                          const DirectionOptions& options = {}) {
    int disagreeing = 0;
    auto direction = [&](double u, double v) -> std::optional<dvec3> {
        std::optional<WeighedDraw> d = sample(u, v);
        if (d && !(std::abs(d->pdf - density(d->dir)) <= 1e-9 * d->pdf)) ++disagreeing;
        return d ? std::optional(d->dir) : std::nullopt;
    };
    expectSamplesFollowDensity(direction, density, options);
    EXPECT_EQ(disagreeing, 0) << "draws whose own pdf is not the density of their direction";
}

}  // namespace brume::sampling::testing
