// gendaylit: a Perez all-weather sky and sun from direct and diffuse light for a date, time and site, or
// for given sun angles, as Radiance's gendaylit (see man/gendaylit.1).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>

#include "sky/daylit_sky.h"
#include "sky/sky_command.h"
#include "util/error.h"

using namespace brume;

namespace {

// x(T) below and above 7000 K (4 + 4 coefficients), y(x) (3). Single precision, as gendaylit keeps them:
// its output shows it (-4842999808.000000). Float literals: see perez.cpp on GCC and -frounding-math.
using Locus = std::array<float, 11>;

// Daylight locus of the skies measured in Berlin (Diakite), gendaylit's default for -C.
constexpr Locus kBerlinLocus = {-4.843e9f, 2.5568e6f, 0.24282e3f, 0.23258f, -4.843e9f, 2.5568e6f,
                                0.24282e3f, 0.23258f, -1.2848f,  1.7519f,  -0.093786f};
// CIE 15 daylight locus: x from 1/T below and above 7000 K, y quadratic in x.
constexpr Locus kCieLocus = {-4.607e9f, 2.9678e6f, 0.09911e3f, 0.244063f, -2.0064e9f, 1.9018e6f,
                             0.24748e3f, 0.23704f, -3.0f, 2.87f, -0.275f};

struct Options {
    DaylitRequest sky;
    Site site;
    int year = 0;
    bool cloudy = false;  // -c: no sun, no limit on the sun's altitude
    bool colour = false;  // -C
    Locus locus = kBerlinLocus;
    double interval = 0;  // -i, minutes
};

void addInputOptions(OptionTable& t, DaylitRequest& sky) {
    auto input = [&sky](DaylitInput kind, const char* name) {
        return [&sky, kind, name](const std::vector<std::string>& a) {
            sky.input = kind;
            sky.first = toReal(name, a[0]);
            sky.second = a.size() > 1 ? toReal(name, a[1]) : 0;
        };
    };
    t.add("-P", 2, "Perez parameters: epsilon delta", input(DaylitInput::PerezParameters, "-P"));
    t.add("-W", 2, "direct normal and diffuse horizontal irradiance (W/m2)", input(DaylitInput::NormalIrradiance, "-W"));
    t.add("-L", 2, "direct normal and diffuse horizontal illuminance (lx)", input(DaylitInput::NormalIlluminance, "-L"));
    t.add("-G", 2, "direct horizontal and diffuse horizontal irradiance (W/m2)",
          input(DaylitInput::HorizontalIrradiance, "-G"));
    t.add("-E", 1, "global horizontal irradiance (W/m2), split by Erbs' model", input(DaylitInput::GlobalIrradiance, "-E"));
    t.add("-O", 1, "output: 0 visible radiance (default), 1 solar radiance, 2 luminance", [&sky](const auto& a) {
        int unit = toInt("-O", a[0]);
        if (unit < 0 || unit > 2) throw Error("bad output specification -O " + a[0]);
        sky.output = DaylitOutput(unit);
    });
}

OptionTable makeTable(Options& o) {
    OptionTable t;
    addInputOptions(t, o.sky);
    t.add("+s", 0, "with the sun (default)", [&o](const auto&) { o.cloudy = false, o.sky.sun = true; });
    t.add("-s", 0, "without the sun", [&o](const auto&) { o.cloudy = false, o.sky.sun = false; });
    for (const char* name : {"-c", "+c"})
        t.add(name, 0, "cloudy: without the sun", [&o](const auto&) { o.cloudy = true, o.sky.sun = false; });
    t.add("-C", 0, "coloured sky (overcast and clear skies)", [&o](const auto&) { o.colour = true; });
    t.add("-CIE", 0, "CIE daylight locus for -C", [&o](const auto&) { o.locus = kCieLocus; });
    t.add("-l", 7, "daylight locus for -C: x(T) = l1/T^3+l2/T^2+l3/T+l4, y = l5 x^2+l6 x+l7", [&o](const auto& a) {
        for (int i = 0; i < 7; ++i) o.locus[i < 4 ? i : i + 4] = float(toReal("-l", a[i]));
        std::copy_n(o.locus.begin(), 4, o.locus.begin() + 4);
    });
    t.add("-w", 0, "no warnings", [](const auto&) { setWarningsEnabled(false); });
    t.add("-i", 1, "time interval of the measurements (minutes)", [&o](const auto& a) {
        o.interval = toReal("-i", a[0]);
        if (o.interval < 0) throw Error("time interval negative");
    });
    t.add("-d", 1, "dew point (degrees C, -40 to 40) for the precipitable water", [&o](const auto& a) {
        double dewPoint = toReal("-d", a[0]);
        if (dewPoint >= -40 && dewPoint <= 40) o.sky.dewPoint = dewPoint;
    });
    for (const char* name : {"-t", "-b", "-R"}) t.add(name, 1, "no effect (accepted as gendaylit accepts it)", [](const auto&) {});
    addSiteOptions(t, o.sky.groundReflectance, o.site, o.year);
    return t;
}

const std::string kUsage =
    "usage: gendaylit month day hour [-y year] -P|-W|-L|-G|-E values [options]\n"
    "   or: gendaylit -ang altitude azimuth -P|-W|-L|-G|-E values [options]\n"
    "   or: gendaylit -defaults\n";

// Radiance's -defaults text; it lists a turbidity gendaylit has no use for.
void printDefaults() {
    Options o;
    printSiteDefaults(o.sky.groundReflectance, 0.1, "Atmospheric betaturbidity", o.site);
}

// Radiance's gendaylit echoes its arguments as given, without quoting.
void printCommand(int argc, char** argv) {
    std::fputs("#", stdout);
    for (int i = 0; i < argc; ++i) std::printf(" %s", argv[i]);
    std::fputs("\n", stdout);
}

// gendaylit's degrees (see degrees() in sky_command.h).
void printSunPosition(double solarTime, const SunAngles& sun) {
    brume::printSunPosition(solarTime, sun.altitude * 180 / kPi, sun.azimuth * 180 / kPi);
}

void printErrorSky(double solarTime, const SunAngles& sun) {
    printSunPosition(solarTime, sun);
    glm::dvec3 d = sunDirection(sun);
    std::printf("\nvoid brightfunc skyfunc\n2 skybright perezlum.cal\n0\n"
                "10 0.00 0.00  0.000 0.000 0.000 0.000 0.000  %f %f %f \n", d.x, d.y, d.z);
}

void printSkyFunction(const DaylitSky& sky, const glm::dvec3& d, bool colour, const Locus& locus) {
    const PerezCoefficients& c = sky.coefficients;
    if (!colour) {
        std::printf("\nvoid brightfunc skyfunc\n2 skybright perezlum.cal\n0\n"
                    "10 %.3e %.3e %lf %lf %lf %lf %lf %f %f %f \n",
                    sky.diffuseNormalisation, sky.groundRadiance, c.a, c.b, c.c, c.d, c.e, d.x, d.y, d.z);
        return;
    }
    std::printf("\nvoid colorfunc skyfunc\n4 skybright_r skybright_g skybright_b perezlum_c.cal\n0\n"
                "22 %.3e %.3e %lf %lf %lf %lf %lf %f %f %f %f",
                sky.diffuseNormalisation, sky.groundRadiance, c.a, c.b, c.c, c.d, c.e, d.x, d.y, d.z,
                sky.condition.clearness);
    for (float l : locus) std::printf(" %f", l);
    std::puts("");
}

void printSky(const DaylitSky& sky, double solarTime, const SunAngles& sun, const Options& o) {
    printSunPosition(solarTime, sun);
    std::printf("# epsilon, delta, atmospheric precipitable water content : %.4f %.4f %.4f \n",
                sky.condition.clearness, sky.condition.brightness, sky.water);
    glm::dvec3 d = sunDirection(sun);
    char radiance[64] = "0.0 0.0 0.0";  // no direct light at epsilon 1
    if (sky.condition.clearness > 1)
        std::snprintf(radiance, sizeof radiance, "%.3e %.3e %.3e", sky.solarRadiance, sky.solarRadiance, sky.solarRadiance);
    char diameter[32];
    std::snprintf(diameter, sizeof diameter, "%f", kDaylitSunDiameter);
    if (o.sky.sun) printSolarSource(radiance, d, diameter);
    // The colour model (Diakite) covers overcast and clear skies only.
    bool colour = o.colour && !(sky.condition.clearness > 1.065 && sky.condition.clearness < 4.5);
    if (o.colour && !colour) warn("intermediate sky (epsilon " + std::to_string(sky.condition.clearness) + "): no colour model, no colour output");
    printSkyFunction(sky, d, colour, o.locus);
}

// The solar time of a daylight time step, or none when the sun is down. With -i, measurements stand for
// the interval centred on the time given, so a step around sunrise or sunset moves to the middle of its
// daylit part (gendaylit's correction).
std::optional<double> daylightSolarTime(double st, int day, const Site& site, double interval, const LocalTime& t) {
    // Half the interval in hours, in single precision as gendaylit has it.
    double rise = sunriseSolarTime(day, site), set = sunsetSolarTime(day, site), half = float(interval) / 120.0f;
    char when[64];
    std::snprintf(when, sizeof when, " at time step %d %d %.3f", t.month, t.day, t.hour);
    if (std::abs(rise - st) <= half && interval > 0) st = (st + half + rise) / 2, warn(std::string("solar position corrected") + when);
    if (std::abs(set - st) < half) st = (st - half + set) / 2, warn(std::string("solar position corrected") + when);
    if (st < rise - half || st > set + half) {
        warn(std::string("sun below the horizon") + when + ", printing error sky");
        return std::nullopt;
    }
    return st;
}

int run(int argc, char** argv) {
    Options o;
    OptionTable table = makeTable(o);
    std::optional<SkyWhen> when = parseSkyCommand({argv + 1, argv + argc}, table, kUsage, o.site, o.year);
    if (!when) return printDefaults(), 0;
    if (!when->fromAngles && (when->time.hour < 0 || when->time.hour >= 24))
        throw UsageError("bad hour", kUsage + table.usage());
    printCommand(argc, argv);
    SunAngles sun = when->angles;
    double solarTime = 0;  // gendaylit prints 0 with -ang
    if (!when->fromAngles) {
        SunDeclination d = sunDeclination(when->time, o.site);
        int day = dayOfYear(when->time.month, when->time.day);
        std::optional<double> st = daylightSolarTime(d.solarTime, day, o.site, o.interval, when->time);
        solarTime = st.value_or(d.solarTime);
        sun = sunAngles(d.declination, solarTime, o.site);
        if (!st) return printErrorSky(solarTime, sun), 0;
        o.sky.dayNumber = day;
    }
    if (!o.cloudy && sun.altitude > 87 * kDegree) {
        warn("sun too close to zenith, reducing altitude to 87 degrees");
        sun.altitude = 87 * kDegree;
    }
    DaylitSky sky = makeDaylitSky(o.sky, sun);
    for (const std::string& line : sky.comments) std::puts(line.c_str());
    if (sky.error) printErrorSky(solarTime, sun);
    else printSky(sky, solarTime, sun, o);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    setProgramName(argv[0]);
    return runReportingErrors([&] { return run(argc, argv); });
}
