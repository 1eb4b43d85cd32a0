// Brume's standard .cal files (lib/cal/library/) against Radiance 6.1's own.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "cal/embedded.h"
#include "cal/parser.h"
#include "cal/testing.h"
#include "scene_text.h"

namespace brume::cal {
namespace {

using testing::Calc;
using Vec = std::array<double, 3>;

struct Reference {
    const char* expr;
    double value;
};

// Radiance 6.1's rcalc with its rayinit.cal: rcalc -f rayinit.cal -n -od -e 'va(i)=select(i,1,2,3);
// vb(i)=select(i,4,5,6)' -e '$1=expr'.
constexpr Reference kRayinit[] = {
    {"abs(-3)", 3},
    {"sgn(-2)", -1},
    {"sq(3)", 9},
    {"frac(-1.25)", 0.75},
    {"mod(-7,3)", 2},
    {"mod(7.5,2)", 1.5},
    {"tri(5,2)", 1},
    {"tri(-1.5,2)", 1.5},
    {"linterp(.25,2,6)", 3},
    {"bound(0,1.5,1)", 1},
    {"hermite(1,2,.5,-.5,.3)", 1.321},
    {"bezier(0,1,3,2,.4)", 1.4240000000000002},
    {"bspline(1,2,4,3,.6)", 3.1026666666666665},
    {"fade(1,.5,2)", 0.6},
    {"fade(1,.5,20)", 0.5},
    {"unif2norm(.9)", 1.281728756502709},
    {"unif2norm(.1)", -1.281728756502709},
    {"unif2norm(.5)", -1.0100667546808495e-07},
    {"and(1,-1)", -1},
    {"or(-1,2)", 2},
    {"not(3)", -1},
    {"xor(1,1)", -1},
    {"inside(0,.5,1)", 0.5},
    {"clip(1.3)", 1},
    {"noneg(-2)", 0},
    {"grey(1,.5,.25)", 0.61633425225},
    {"clipgrey(2,2,2)", 1},
    {"Acos(1.5)", 0},
    {"Asin(-2)", -1.5707963267948966},
    {"Atan2(0,0)", 0},
    {"Atan2(1,1)", 0.7853981633974483},
    {"Exp(-200)", 0},
    {"Sqrt(-4)", 0},
    {"dot(va,vb)", 32},
    {"cross(1,va,vb)", -3},
    {"cross(2,va,vb)", 6},
    {"cross(3,va,vb)", -3},
    {"PI", 3.141592653589793},
    {"DEGREE", 0.017453292519943295},
    {"red(-1,2,3)+green(1,2,3)+blue(1,2,-3)", 2},
    {"clip_r(2,0,0)+clip_g(0,-1,0)+clip_b(0,0,.5)", 1.5},
    {"noop(4)", 4},
};

TEST(CalStandardLibrary, RayinitMatchesRadiance) {
    Calc calc;
    calc.library.loadText("va(i) = select(i, 1, 2, 3); vb(i) = select(i, 4, 5, 6);", "test.cal");
    for (const Reference& r : kRayinit) EXPECT_NEAR(calc(r.expr), r.value, 1e-15 + 1e-14 * std::abs(r.value)) << r.expr;
}

TEST(CalStandardLibrary, ChannelNamesAreRadiancesChannelNumbers) {
    const char* names[] = {nullptr, "Dx", "Dy", "Dz", "Nx", "Ny", "Nz", "Px", "Py", "Pz", "T", "Rdot", "S", "Tx",
                           "Ty", "Tz", "Ix", "Iy", "Iz", "Jx", "Jy", "Jz", "Kx", "Ky", "Kz", "Ts", "Lu", "Lv",
                           "NxP", "NyP", "NzP", "RdotP", "CrP", "CgP", "CbP", "DxA", "DyA", "DzA"};
    static_assert(std::size(names) == kChannelCount);
    Calc calc;
    for (int c = 1; c < kChannelCount; ++c) calc.channels[c] = c;
    for (int c = 1; c < kChannelCount; ++c) EXPECT_EQ(calc(names[c]), c) << names[c];
}

// Brume's own files: a user's RAYPATH (Radiance's library, say) would put other files of the same names first.
// reinhart.cal wants MF from its user, as Radiance's does.
TEST(CalStandardLibrary, EveryDefinitionOfEveryFileCompiles) {
    test::ScopedRayPath none(nullptr);
    Library library;
    library.loadText("MF : 2;", "user.cal");
    Compiler compiler(library);
    for (const EmbeddedFile& file : embeddedCalFiles()) {
        Scope scope = library.loadFile(std::string(file.name));
        for (const Definition& d : parseDefinitions(file.text, std::string(file.name))) {
            SCOPED_TRACE(std::string(file.name) + ": " + d.name);
            if (d.isFunction())
                EXPECT_NO_THROW(compiler.function(d.name, static_cast<int>(d.params.size()), scope, {}));
            else
                EXPECT_NO_THROW(compiler.expression(d.name, scope, {}));
        }
    }
}

// A pattern's transform: "-rx 20 -rz 30" or none, then "-s scale".
struct Transform {
    bool rotated;
    double scale;
};

// The channels Radiance's rtrace gives a pattern with transform `xf` for a ray (origin o, direction d)
// hitting the plane z = 0 (normal +z), the ray's first hit.
Channels patternChannels(const Vec& o, Vec d, const Transform& xf) {
    double len = std::hypot(d[0], d[1], d[2]);
    for (double& c : d) c /= len;
    double t = -o[2] / d[2];
    // World to pattern: undo the scale, then rotate by -30 degrees about z and -20 about x.
    auto toPattern = [&](const Vec& v) {
        const double a = xf.rotated ? std::numbers::pi / 6 : 0, b = xf.rotated ? std::numbers::pi / 9 : 0;
        Vec w = {std::cos(a) * v[0] + std::sin(a) * v[1], -std::sin(a) * v[0] + std::cos(a) * v[1], v[2]};
        return Vec{w[0], std::cos(b) * w[1] + std::sin(b) * w[2], -std::sin(b) * w[1] + std::cos(b) * w[2]};
    };
    Channels ch{};
    auto put = [&](int first, const Vec& v, double divide) {
        for (int i = 0; i < 3; ++i) ch[first + i] = v[i] / divide;
    };
    put(Dx, toPattern(d), 1);
    put(Nx, toPattern({0, 0, 1}), 1);
    put(Px, toPattern({o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]}), xf.scale);
    put(Ix, toPattern({1, 0, 0}), 1);
    put(Jx, toPattern({0, 1, 0}), 1);
    put(Kx, toPattern({0, 0, 1}), 1);
    ch[T] = ch[Ts] = t / xf.scale;
    ch[Rdot] = -d[2];
    ch[S] = 1 / xf.scale;
    return ch;
}

struct RayReference {
    const char* expr;
    std::array<double, 8> values;
};

const Vec kOrigins[] = {{.3, .2, 1}, {-1, .5, 2}, {2, -1, .5}, {.1, .1, 3},
                        {.5, .3, 1}, {.9, .8, 1}, {1.2, -.4, 1}, {-.3, 1.7, 1}};
const Vec kDirections[] = {{-.3, -.5, -.8}, {.6, .1, -.7}, {-.1, .7, -.4}, {.05, -.02, -1},
                           {0, 0, -1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}};

// Each expression for the rays above, as Radiance's rtrace gives it for a brightfunc on a glow
// polygon at z = 0 with the given file, real arguments and transform (rtrace -ov -fad; the values pass
// through Radiance's float colours, so they hold 7 digits).
void expectRadianceValues(const std::string& file, const std::vector<double>& args, const Transform& xf,
                          std::initializer_list<RayReference> references) {
    Calc calc;
    calc.args = args;
    Scope scope = calc.library.loadFile(file);
    for (const RayReference& r : references)
        for (size_t i = 0; i < r.values.size(); ++i) {
            if (std::isnan(r.values[i])) continue;
            calc.channels = patternChannels(kOrigins[i], kDirections[i], xf);
            EXPECT_NEAR(calc(r.expr, scope), r.values[i], 2e-6 * (1 + std::abs(r.values[i]))) << r.expr << " ray " << i;
        }
}

constexpr double X = NAN;  // rays not traced for that file
constexpr Transform kRotated{true, 1}, kScaled{false, .6};

TEST(CalStandardLibrary, SourceCalMatchesRadiance) {
    expectRadianceValues("source.cal", {2, .5, .3, .2}, kRotated, {
        {"src_theta", {131.422592, 129.094742, 137.641098, 157.5, X, X, X, X}},
        {"src_phi", {46.6241112, 142.319305, 241.236145, 94.9849777, X, X, X, X}},
        {"src_phi2", {46.6241112, 142.319305, 118.763855, 94.9849777, X, X, X, X}},
        {"src_phi4", {46.6241112, 37.6806908, 61.236145, 85.0150223, X, X, X, X}},
        {"srcB_vert", {142.103455, -135.75354, -156.30986, -177.938644, X, X, X, X}},
        {"srcB_horiz", {-140.51796, -143.045975, 141.364548, -157.57666, X, X, X, X}},
        {"srcB_vert2", {142.103455, 135.75354, 156.30986, 177.938644, X, X, X, X}},
        {"corr(3)", {6, 6, 6, 6, X, X, X, X}},
        {"flatcorr(3)", {7.42462111, 7.94881582, 12.186058, 6.0086937, X, X, X, X}},
        {"boxcorr(3)", {32.494957, 33.5411453, 31.6860771, 33.5756912, X, X, X, X}},
        {"lboxcorr(3)", {48.6113091, 41.6079597, 17.2421074, 36.2676353, X, X, X, X}},
        {"cylcorr(3)", {24.7541218, 24.9755898, 24.3747692, 25.1250134, X, X, X, X}},
        {"U", {0.811215103, -2.95727229, -4.56492901, -0.691498339, X, X, X, X}},
        {"V", {0.966495097, -0.945282578, 3.05757785, 0.264191985, X, X, X, X}},
    });
}

TEST(CalStandardLibrary, SourceCorrectionWithOneArgumentIgnoresTheMultiplier) {
    // As Radiance's source_corr: A1 scales the value only when there are two or more real arguments.
    expectRadianceValues("source.cal", {2}, kRotated, {{"corr(3)", {3, 3, 3, 3, X, X, X, X}}});
}

TEST(CalStandardLibrary, TiltCalMatchesRadiance) {
    expectRadianceValues("tilt.cal", {}, kRotated, {
        {"tilt_ang", {20, 20, 20, 20, X, X, X, X}},
        {"tilt_xang", {70, 70, 70, 70, X, X, X, X}},
        {"tilt_ang2", {20, 20, 20, 20, X, X, X, X}},
        {"tilt_xang2", {70, 70, 70, 70, X, X, X, X}},
    });
}

TEST(CalStandardLibrary, TmeshCalMatchesRadiance) {
    expectRadianceValues("tmesh.cal", {2, .1, .2, .3, .4, .5, .6, .7, .8, .9}, kRotated, {
        {"u", {0.210129708, 0.461906254, 0.259592444, 0.306668699, 0.360144496, 0.463577569, 0.206056118, 0.66390121}},
        {"v", {0.333706468, 0.156482667, 0.733175755, 0.65214771, 0.837813139, 0.185857385, 0.491024882, 0.59828192}},
        {"dx", {0.347989172, 0.207042754, 0.180813864, 0.249184072, 0.22499685, 0.202088147, 0.218944818, 0.216429636}},
        {"dz", {-0.182400271, -0.109982371, -0.0991490036, -0.129069671, -0.117857888, -0.107875206, -0.115161002, -0.11405284}},
    });
}

TEST(CalStandardLibrary, IllumCalMatchesRadiance) {
    expectRadianceValues("illum.cal", {.6, .8, 0, -.8, .6, 0, 0, 0, 1}, kRotated, {
        {"il_alt", {-0.661607563, -0.630604565, -0.738938808, -0.923879504, -0.939692616, -0.939692616, -0.939692616, -0.939692616}},
        {"il_azi", {3.95533681, 5.6255331, 1.06877232, 4.79939318, 4.71238899, 4.71238899, 4.71238899, 4.71238899}},
        {"il_alth", {0.437724531, 0.397662103, 0.546030581, 0.853553355, 0.883022249, 0.883022249, 0.883022249, 0.883022249}},
        {"il_azih", {6.16963434, 1.55664527, 3.28306985, 0.730505347, 0.643501103, 0.643501103, 0.643501103, 0.643501103}},
    });
}

// Radiance 6.1 does not ship picture.cal; the reference is the classic one (Radiance's supplementary
// library) run by Radiance 6.1's rtrace, with pattern transform "-s 0.6".
TEST(CalStandardLibrary, PictureCalMatchesRadiancesClassicFile) {
    expectRadianceValues("picture.cal", {1.5, .2, .3, .5}, kScaled, {
        {"pic_u", {-0.125, 1.19047618, 3.125, 0.416666657, 0.833333313, 1.5, 2, -0.5}},
        {"inpic", {0, 0, 0, 1, 1, 0, 0, 0}},
        {"tile_u", {0.875, 0.190476194, 0.125, 0.416666657, 0.833333313, 0.5, 0, 0.5}},
        {"tile_v", {0.791666687, 1.30952382, 1.29166663, 0.0666666701, 0.5, 1.33333337, 0.833333313, 1.33333337}},
        {"match_u", {0.125, 0.809523821, 0.875, 0.416666657, 0.833333313, 0.5, 0, 0.5}},
        {"match_v", {0.708333313, 1.30952382, 0.208333328, 0.0666666701, 0.5, 1.33333337, 0.666666687, 0.166666672}},
        {"stag_u", {0.875, 0.690476179, 0.125, 0.916666687, 0.333333343, 0, 0, 0.5}},
        {"infore(0.4,0.6,1)", {0, 0, 0, 0, 0, 0, 0, 0}},
        {"infore(0.5,0.3,0.2)", {0, 0, 0, 1, 1, 0, 0, 0}},
        {"fadered(0.5,0,0)", {0.487760186, 0.451043636, 0.491645575, 0.43986088, 0.491891891, 0.491891891, 0.491891891, 0.491891891}},
    });
    expectRadianceValues("picture.cal", {.6, .2, .3, .5}, kScaled, {
        {"inpic", {0, 0, 0, 1, 1, 0, 0, 0}},
        {"tile_u", {1.54166663, 1.19047618, 1.45833337, 0.416666657, 0.833333313, 1.5, 0.333333343, 1.16666663}},
        {"tile_v", {0.291666657, 0.309523821, 0.791666687, 0.0666666701, 0.5, 0.333333343, 0.333333343, 0.833333313}},
        {"match_u", {0.125, 1.19047618, 0.208333328, 0.416666657, 0.833333313, 1.5, 1.33333337, 0.5}},
        {"stag_u", {1.54166663, 1.19047618, 1.45833337, 1.25, 0, 1.5, 0.333333343, 0.333333343}},
    });
}

}  // namespace
}  // namespace brume::cal
