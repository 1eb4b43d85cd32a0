// epw2wea: an EnergyPlus weather file as DAYSIM's .wea (direct normal and diffuse horizontal irradiance at
// the middle of each hour), as Radiance's epw2wea writes it (see man/epw2wea.1).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>

#include "sky/weather_tape.h"
#include "util/error.h"

using namespace brume;

namespace {

const char* const kUsage = "usage: epw2wea [-a] file-name.epw [file-name.wea]\n";

// The header, fields copied as the EPW file writes them where Radiance copies them.
void writeHeader(std::FILE* out, const WeatherSite& site) {
    const std::vector<std::string>& f = site.locationFields;
    std::fprintf(out, "place %s_%s\nlatitude %s\nlongitude %f\n", f[1].c_str(), f[3].c_str(), f[6].c_str(),
                 -std::atof(f[7].c_str()));
    // Radiance truncates the zone to whole hours (atoi): +5.5 would be India's +5. Brume keeps the half.
    double meridian = -15.0 * site.timeZone;
    if (meridian == double(long(meridian))) std::fprintf(out, "time_zone %.0f\n", meridian);
    else std::fprintf(out, "time_zone %g\n", meridian);
    std::string elevation = f[9].substr(0, f[9].find_first_of(" \t"));
    std::fprintf(out, "site_elevation %s\nweather_data_file_units 1\n", elevation.c_str());
}

int run(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    bool extra = false;
    while (args.size() > 1 && args[0].size() > 1 && args[0][0] == '-') {
        if (args[0] != "-a") throw UsageError("unknown option: " + args[0], kUsage);
        extra = !extra;
        args.erase(args.begin());
    }
    if (args.empty() || args.size() > 2) throw UsageError("wrong number of arguments", kUsage);
    std::ifstream in(args[0]);
    if (!in) throw Error(args[0] + ": cannot open for reading");
    WeatherTape tape(in, args[0]);
    if (tape.units() != WeatherUnits::Epw) throw Error(args[0] + ": this does not seem to be an EPW file");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file{nullptr, std::fclose};
    if (args.size() == 2) {
        file.reset(std::fopen(args[1].c_str(), "w"));
        if (!file) throw Error(args[1] + ": cannot open for writing");
    }
    std::FILE* out = file ? file.get() : stdout;
    writeHeader(out, tape.site());
    while (std::optional<WeatherRecord> r = tape.next()) {
        // EPW's missing-value code, where the file has one.
        double direct = r->direct.value_or(9999), diffuse = r->diffuse.value_or(9999);
        std::fprintf(out, "%d %d %.3f %.0f %.0f", r->month, r->day, r->hour, float(direct), float(diffuse));
        if (extra) std::fprintf(out, " %.3f %.1f", float(r->aerosolDepth.value_or(0.999)), std::trunc(r->skyCover.value_or(99)) / 10);
        std::fputc('\n', out);
    }
    if (file && std::fflush(file.get()) != 0) throw Error(args[1] + ": write error");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    setProgramName(argv[0]);
    return runReportingErrors([&] { return run(argc, argv); });
}
