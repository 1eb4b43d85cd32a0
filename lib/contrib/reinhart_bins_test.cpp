// ReinhartBins gives the bins of Brume's reinhartb.cal, evaluated as a .cal, to the last bit: for directions
// spread over the sphere, the axes and the patches' edges, in the frames rfluxmtx sets up.
#include "contrib/reinhart_bins.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "cal/compiler.h"
#include "cal/embedded.h"
#include "cal/evaluator.h"
#include "sampling/random.h"

using namespace brume;

namespace {

std::string shippedReinhartb() {
    for (const EmbeddedFile& f : cal::embeddedCalFiles())
        if (f.name == "reinhartb.cal") return std::string(f.text);
    ADD_FAILURE() << "no reinhartb.cal";
    return {};
}

void expectSameBins(const ReinhartFrame& f, const std::string& parameters) {
    cal::Library library;
    library.loadText(shippedReinhartb(), "reinhartb.cal");
    library.redefine(parameters, "-p");
    cal::Compiler compiler(library);
    cal::ExprId rbin = compiler.expression("rbin", {}, {"test", 1});
    cal::Program program = std::move(compiler).finish();
    cal::Evaluator evaluator(program);
    ReinhartBins native(f);
    auto check = [&](glm::dvec3 d) {
        d = glm::normalize(d);
        cal::Channels channels{};
        channels[cal::Dx] = d.x, channels[cal::Dy] = d.y, channels[cal::Dz] = d.z;
        evaluator.begin(channels);
        double expected = evaluator(rbin);
        ASSERT_EQ(native.bin(d), expected) << parameters << " at " << d.x << " " << d.y << " " << d.z;
    };
    Random rng(7, 1);
    for (int i = 0; i < 20000; ++i) {
        double z = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform(), r = std::sqrt(1 - z * z);
        check({r * std::cos(phi), r * std::sin(phi), z});
    }
    // The axes, and directions on the edges of rows and columns of patches (for a frame facing up).
    for (glm::dvec3 d : {glm::dvec3(1, 0, 0), {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}}) check(d);
    for (int row = 0; row <= 28; ++row)
        for (int az = 0; az < 120; ++az) {
            double elev = row * 90.0 / (7 * f.mf + .5) * M_PI / 180, a = az * 3.0 * M_PI / 180;
            check({std::cos(elev) * std::sin(a), std::cos(elev) * std::cos(a), std::sin(elev)});
            check({std::cos(elev) * std::sin(a), std::cos(elev) * std::cos(a), -std::sin(elev)});
        }
}

TEST(ReinhartBins, AreReinhartbCalsBinsToTheLastBit) {
    expectSameBins({1, 1, {0, 0, -1}, {0, 1, 0}}, "MF=1;rNx=0;rNy=0;rNz=-1;Ux=0;Uy=1;Uz=0;RHS=+1;");
    expectSameBins({2, -1, {0, 1, 0}, {0, 0, 1}}, "MF=2;rNx=0;rNy=1;rNz=0;Ux=0;Uy=0;Uz=1;RHS=-1;");
    expectSameBins({4, 1, {0, 0, 1}, {0, 1, 0}}, "MF=4;rNx=0;rNy=0;rNz=1;Ux=0;Uy=1;Uz=0;RHS=1;");
    glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.8, 0.2));
    char p[200];
    std::snprintf(p, sizeof p, "MF=3;rNx=%.17g;rNy=%.17g;rNz=%.17g;Ux=0;Uy=0;Uz=1;RHS=1;", n.x, n.y, n.z);
    expectSameBins({3, 1, n, {0, 0, 1}}, p);
}

}  // namespace
