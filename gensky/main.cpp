// gensky: a CIE sky (and sun) for a date, time and site, or for given sun angles, as Radiance's gensky
// (see man/gensky.1).
#include <cstdio>
#include <optional>

#include "sky/cie_sky.h"
#include "sky/sky_command.h"
#include "util/error.h"
#include "util/header.h"

using namespace brume;

namespace {

struct Options {
    CieSkyRequest sky;
    Site site;
    int year = 0;
};

OptionTable makeTable(Options& o) {
    OptionTable t;
    auto type = [&o](CieSkyType type, bool sun) {
        return [&o, type, sun](const std::vector<std::string>&) { o.sky.type = type, o.sky.sun = sun; };
    };
    t.add("+s", 0, "CIE clear sky with sun (default)", type(CieSkyType::Clear, true));
    t.add("-s", 0, "CIE clear sky without sun", type(CieSkyType::Clear, false));
    t.add("+i", 0, "CIE intermediate sky with sun", type(CieSkyType::Intermediate, true));
    t.add("-i", 0, "CIE intermediate sky without sun", type(CieSkyType::Intermediate, false));
    t.add("-c", 0, "CIE overcast sky", type(CieSkyType::Overcast, false));
    t.add("-u", 0, "uniform cloudy sky", type(CieSkyType::Uniform, false));
    auto given = [](GivenValue& to, GivenValue::Unit unit, const char* name) {
        return [&to, unit, name](const std::vector<std::string>& a) { to = {unit, toReal(name, a[0])}; };
    };
    t.add("-b", 1, "zenith radiance (W/sr/m2)", given(o.sky.zenith, GivenValue::Unit::Radiance, "-b"));
    t.add("-B", 1, "zenith radiance from horizontal diffuse irradiance (W/m2)",
          given(o.sky.zenith, GivenValue::Unit::Irradiance, "-B"));
    t.add("-r", 1, "solar radiance (W/sr/m2); 0: no sun", given(o.sky.solar, GivenValue::Unit::Radiance, "-r"));
    t.add("-R", 1, "solar radiance from horizontal direct irradiance (W/m2)",
          given(o.sky.solar, GivenValue::Unit::Irradiance, "-R"));
    t.add("-t", 1, "turbidity (default 2.45)", [&o](const auto& a) { o.sky.turbidity = toReal("-t", a[0]); });
    addSiteOptions(t, o.sky.groundReflectance, o.site, o.year);
    return t;
}

const std::string kUsage =
    "usage: gensky month day time [options]\n"
    "   or: gensky -ang altitude azimuth [options]\n"
    "   or: gensky -defaults\n";

// Radiance's -defaults text: the sky type, ground, turbidity and site.
void printDefaults() {
    Options o;
    std::puts("+s\t\t\t\t# Sunny sky with sun");
    printSiteDefaults(o.sky.groundReflectance, o.sky.turbidity, "Atmospheric turbidity", o.site);
}

void printSky(const CieSky& sky) {
    std::printf("# Ground ambient level: %.1f\n", sky.ambientLevel);
    if (sky.sun) {
        char radiance[64];
        std::snprintf(radiance, sizeof radiance, "%.3e %.3e %.3e", sky.solarRadiance, sky.solarRadiance, sky.solarRadiance);
        printSolarSource(radiance, sky.sunDirection, "0.5");
    }
    std::printf("\nvoid brightfunc skyfunc\n2 skybr skybright.cal\n0\n");
    if (isOvercast(sky.type))
        std::printf("3 %d %.3e %.3e\n", int(sky.type), sky.zenithRadiance, sky.groundRadiance);
    else
        std::printf("7 %d %.3e %.3e %.3e %f %f %f\n", int(sky.type), sky.zenithRadiance, sky.groundRadiance,
                    sky.zenithNormalisation, sky.sunDirection.x, sky.sunDirection.y, sky.sunDirection.z);
}

// The sun's position; for a date and time, also printed. Sunny skies keep the sun at least 3° from the
// zenith, where the clear sky's zenith luminance, proportional to tan(altitude), grows without bound.
SunAngles sunPosition(const SkyWhen& when, const Options& o) {
    SunAngles sun = when.angles;
    if (!when.fromAngles) {
        SunDeclination d = sunDeclination(when.time, o.site);
        sun = sunAngles(d.declination, d.solarTime, o.site);
        printSunPosition(d.solarTime, degrees(sun.altitude), degrees(sun.azimuth));
    }
    if (!isOvercast(o.sky.type) && sun.altitude > 87 * kDegree) {
        warn("sun too close to zenith, reducing altitude to 87 degrees");
        std::puts("# warning - sun too close to zenith, reducing altitude to 87 degrees");
        sun.altitude = 87 * kDegree;
    }
    return sun;
}

int run(int argc, char** argv) {
    Options o;
    OptionTable table = makeTable(o);
    std::optional<SkyWhen> when = parseSkyCommand({argv + 1, argv + argc}, table, kUsage, o.site, o.year);
    if (!when) return printDefaults(), 0;
    if (o.year != 0 && (o.year < 1950 || o.year > 2050)) warn("year should be in range 1950-2050");
    std::vector<std::string> command(argv, argv + argc);
    command[0] = programName();
    std::printf("# %s\n", commandLine(command).c_str());
    printSky(makeCieSky(o.sky, sunPosition(*when, o)));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    setProgramName(argv[0]);
    return runReportingErrors([&] { return run(argc, argv); });
}
