// rfluxmtx's senders: each bin's directions against the density it stands for (chi-square: cosine-weighted for
// h=u, uniform in projected solid angle over a Klems patch, uniform in altitude and azimuth over a Reinhart
// patch), every Klems ray in its own patch in the sender's frame, origins uniform over a concave polygon and
// spread over surfaces by their area projected across the ray, and the sender files refused.
#include "contrib/senders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include <glm/geometric.hpp>

#include "sampling/testing.h"
#include "scratch_dir.h"
#include "util/error.h"

using namespace brume;
using namespace brume::sampling::testing;

namespace {

constexpr double kPi = std::numbers::pi;

Sender senderOf(const std::string& text) {
    std::string path = (brume_test::scratchDir("senders") / "sender.rad").string();
    std::ofstream(path) << text;
    return Sender(path);
}

// A unit square in z = 0 whose normal points down: its rays go up.
std::string square(const std::string& settings) {
    return "#@rfluxmtx " + settings + "\nvoid polygon s 0 0 12 0 0 0  0 1 0  1 1 0  1 0 0\n";
}

// The reverse of a ray's direction in the sender's frame: (along u, along v, along the normal).
dvec3 inFrame(const Sender& s, const dvec3& d) { return {-glm::dot(d, s.u()), -glm::dot(d, s.v()), -glm::dot(d, s.normal())}; }

DirectionOptions about(const Sender& s) {
    DirectionOptions o;
    o.draws = 200'000;
    o.rings = 20, o.sectors = 40;
    o.axis = -s.normal();
    return o;
}

}  // namespace

TEST(Senders, UniformRaysAreCosineWeightedAwayFromTheNormal) {
    Sender s = senderOf(square("h=u u=Y"));
    EXPECT_EQ(s.bins(), 1);
    EXPECT_NEAR(glm::dot(s.normal(), dvec3(0, 0, -1)), 1, 1e-12);
    expectSamplesFollowDensity([&](double u, double v) { return std::optional(s.direction(0, u, v)); },
                               [](const dvec3& d) { return std::max(0.0, d.z) / kPi; }, about(s));
}

TEST(Senders, KlemsRaysAreUniformInProjectedSolidAngleOverTheirPatch) {
    for (const char* h : {"h=kf u=Y", "h=-kq u=X"}) {
        Sender s = senderOf(square(h));
        const KlemsBasis& basis = *KlemsBasis::standard(h[3] == 'f' ? "LBNL/Klems Full" : "LBNL/Klems Quarter");
        ASSERT_EQ(s.bins(), basis.size());
        Random random(7);
        for (int b = 0; b < s.bins(); ++b)
            for (int k = 0; k < 20; ++k) {
                dvec3 local = inFrame(s, s.direction(b, random.uniform(), random.uniform()));
                ASSERT_EQ(basis.index(local), b) << h << " bin " << b;
            }
        for (int b : {0, 5, basis.size() - 1}) {
            auto density = [&](const dvec3& d) {
                dvec3 local = inFrame(s, d);
                return basis.index(local) == b ? local.z / basis.projectedSolidAngle(b) : 0.0;
            };
            // Cells over a cap about the patch: many to a patch, so that their integrals see its edges.
            std::vector<dvec3> spread;
            for (int k = 0; k < 400; ++k) spread.push_back(s.direction(b, random.uniform(), random.uniform()));
            DirectionOptions o = capAround(dvec3(0), spread, about(s));
            expectSamplesFollowDensity([&](double u, double v) { return std::optional(s.direction(b, u, v)); }, density, o);
        }
    }
}

// Reinhart's row 3 (MF 1) holds 24 patches 12.4° high; a patch's directions are uniform in altitude and azimuth,
// dω = cos(altitude) d(altitude) d(azimuth).
TEST(Senders, ReinhartRaysAreUniformInAltitudeAndAzimuthOverTheirPatch) {
    Sender s = senderOf(square("h=r1 u=Y"));
    EXPECT_EQ(s.bins(), 145);
    const int bin = 30 + 30 + 5;  // row 2, patch 5
    const double height = (kPi / 2) / 7.5, width = 2 * kPi / 24;
    auto density = [&](const dvec3& d) {
        dvec3 local = inFrame(s, d);
        double altitude = std::asin(std::clamp(local.z, -1.0, 1.0));
        double azimuth = std::atan2(local.x, -local.y);  // the sender's: from −v toward u
        double column = azimuth / width + 0.5;
        bool inside = altitude >= 2 * height && altitude < 3 * height && column >= 5 && column < 6;
        return inside ? 1 / (height * width * std::cos(altitude)) : 0.0;
    };
    DirectionOptions o = about(s);
    o.rings = 80, o.sectors = 160;
    expectSamplesFollowDensity([&](double u, double v) { return std::optional(s.direction(bin, u, v)); }, density, o);
}

// An L of area 3 (a concave polygon): origins within it, a third of them in its arm beyond x = 1.
TEST(Senders, OriginsAreUniformOverAConcavePolygon) {
    Sender s = senderOf("#@rfluxmtx h=kq u=Y\nvoid polygon l 0 0 18 0 0 0  0 2 0  1 2 0  1 1 0  2 1 0  2 0 0\n");
    const int n = 30000;
    int arm = 0;
    for (int i = 0; i < n; ++i) {
        std::array<double, 6> r = s.ray(i % s.bins(), uint32_t(i / s.bins()), 3);
        ASSERT_EQ(r[2], 0);
        ASSERT_TRUE(r[0] >= 0 && r[1] >= 0 && (r[0] <= 1 || r[1] <= 1)) << r[0] << " " << r[1];
        arm += r[0] > 1;
    }
    // Binomial: σ = √(n p (1 − p)) ≈ 82 draws; within 4σ.
    EXPECT_NEAR(arm, n / 3.0, 4 * std::sqrt(n / 3.0 * 2 / 3));
}

// Two unit squares, one in z = 0 facing down and one tilted 60° about x: rays of a bin leave each in proportion
// to its area projected across them.
TEST(Senders, RaysLeaveEachSurfaceByItsProjectedArea) {
    double c = std::cos(kPi / 3), sn = std::sin(kPi / 3);
    std::ostringstream text;
    text << "#@rfluxmtx h=kf u=Y\nvoid polygon a 0 0 12 0 0 0  0 1 0  1 1 0  1 0 0\n"
         << "void polygon b 0 0 12 5 0 0  5 " << c << " " << sn << "  6 " << c << " " << sn << "  6 0 0\n";
    Sender s = senderOf(text.str());
    EXPECT_EQ(s.surfaces(), 2);
    dvec3 na(0, 0, -1), nb = glm::normalize(glm::cross(dvec3(0, c, sn), dvec3(1, 0, 0)));
    const int bin = 0, n = 20000;
    int fromB = 0;
    dvec3 dir(0);
    for (int i = 0; i < n; ++i) {
        std::array<double, 6> r = s.ray(bin, uint32_t(i), 11);
        fromB += r[0] > 2;
        dir += dvec3(r[3], r[4], r[5]);
    }
    dir = glm::normalize(dir);  // the patch about the normal: its mean direction
    double pa = std::max(0.0, -glm::dot(na, dir)), pb = std::max(0.0, -glm::dot(nb, dir));
    double p = pb / (pa + pb);
    EXPECT_NEAR(fromB, n * p, 4 * std::sqrt(n * p * (1 - p)) + 0.02 * n);  // 2 %: the patch's spread of directions
}

TEST(Senders, BadSendersAreRefused) {
    struct Bad {
        std::string text, message;
    } cases[] = {
        {"#@rfluxmtx h=u\nvoid glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 1 180\n", "cannot use source 's' as a sender"},
        {"void polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n", "missing sender sampling type"},
        {"#@rfluxmtx h=sc4\nvoid polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n", "h=sc4 is not supported"},
        {"#@rfluxmtx h=kf u=Z\nvoid polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n", "up vector coincides with sender normal"},
        {"#@rfluxmtx h=kf\nvoid sphere b 0 0 4 0 0 0 1\n", "no sender surface"},
        {"#@rfluxmtx h=kf\nvoid polygon bow 0 0 12 0 0 0  3 1 0  3 0 0  0 2 0\n", "cannot sample sender polygon 'bow'"},
        {"#@rfluxmtx h=r101\nvoid polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n", "more than 100 subdivisions"},
        {"#@rfluxmtx h=kf\nvoid polygon big 0 0 9 0 0 0 1e300 0 0 0 1e300 0\n", "sender.rad:2: surface element 'big' too large to measure"},
    };
    for (const Bad& b : cases) {
        try {
            senderOf(b.text);
            ADD_FAILURE() << b.text;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(b.message), std::string::npos) << e.what();
        }
    }
}
