// gendaymtx's skies: for each record of a weather tape, a Perez all-weather sky (Perez, Seals & Michalsky
// 1993) sampled at the centres of the sky's patches (SkyPatches), normalised to the record's diffuse
// illuminance, the ground's radiance from the global illuminance, and the sun spread over its nearest
// patches (or, for the 5-phase method's -5, put in the nearest one at its own solid angle). Radiances in
// W/sr/m² of Radiance's visible (-O0, lumens over 179) or solar (-O1) kind.
#pragma once
#include <array>
#include <string>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "sky/sky_patches.h"
#include "sky/solar_position.h"
#include "sky/weather_tape.h"

namespace brume {

using Rgb = std::array<double, 3>;

struct SkyMatrixOptions {
    int subdivisions = 1;            // -m
    double rotation = 0;             // -r: degrees, the sky turned anticlockwise seen from above
    Rgb skyColour{0.96, 1.004, 1.118};  // -c; black with -d
    Rgb sunColour{1, 1, 1};          // black with -s
    Rgb groundReflectance{0.2, 0.2, 0.2};  // -g; black with -d
    bool solarRadiance = false;      // -O1
    int sunPatches = 4;              // patches the sun is spread over
    double sunSolidAngle = 0;        // -5: the sun's own solid angle (sr) in its one patch; 0: the patch's
    double interval = 0;             // -i: minutes a record stands for (sunrise and sunset corrected)
    bool sunHoursOnly = false;       // -u: no columns for records with the sun below the horizon
};

// One record's sky: where the sun is, how bright, and the patches' radiances (or none: a record -u skips).
struct SkyStep {
    WeatherRecord record;
    int minuteOfYear = 0;          // gendaymtx's sun identifier: minutes from January 1st, 0:00
    bool sunInSky = false;         // its centre above -0.2665°
    bool dark = false;             // no light at all (direct + diffuse at most 1e-4)
    glm::dvec3 sunDirection{0.0};
    double directIlluminance = 0;  // lx (solar: W/m² × 179 with -O1)
    std::vector<float> patches;    // 3 per patch, ground first
};

class SkySteps {
public:
    SkySteps(const WeatherSite& site, WeatherUnits units, const SkyMatrixOptions& options);
    const SkyPatches& patches() const { return patches_; }
    // The next record's sky, or none when -u skips it. Records must come in the tape's order (dew points are
    // averaged over three of them, and a leap day shifts the days after it). Throws Error for a record that
    // lacks the irradiances the sky needs; warns of direct light with the sun below the horizon.
    std::optional<SkyStep> step(const WeatherRecord& record);

private:
    // Where the sun is (azimuth east of north, the sky turned), the day of the year, the dew point.
    struct Sky {
        double altitude, azimuth;
        int day;
        double dewPoint;
    };
    double dewPoint(const WeatherRecord& record);
    void computeSky(SkyStep& s, double direct, double diffuse, const Sky& at) const;
    void addSun(SkyStep& s, double altitude, double azimuth) const;

    Site site_;
    WeatherUnits units_;
    SkyMatrixOptions options_;
    SkyPatches patches_;
    double dewPoint_ = 11;   // °C, gendaymtx's default where the tape has none
    float dewHistory_[2] = {-100, -100};
    bool leapDay_ = false;
};

// The sun of a step as gendaymtx -D writes it: a `light` solarN of the sun's radiance (0 when `bright` is false)
// and a `source` sunN 0.533° across, N the step's minute of the year.
std::string sunDescription(const SkyStep& step, const Rgb& sunColour, bool bright);

}  // namespace brume
