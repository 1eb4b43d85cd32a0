#include "integrator/render_options.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <thread>

#include "util/error.h"

namespace brume {

namespace {

void addColor(OptionTable& t, const std::string& name, Spectrum& v, const std::string& help) {
    t.add(name, 3, help,
          [&v, name](const auto& a) {
              v = Spectrum(float(toReal(name, a[0])), float(toReal(name, a[1])), float(toReal(name, a[2])));
          },
          [&v] { return formatReal(v[0]) + " " + formatReal(v[1]) + " " + formatReal(v[2]); });
}

}  // namespace

void addRenderOptions(OptionTable& t, RenderSettings& s, bool& irradianceAtHit) {
    t.addBool("-u", s.randomSampling, "uncorrelated random sampling (- : reproducible, same result for any -n)");
    t.addBool("-bv", s.materials.backVisible, "back face visibility");
    t.addBool("-i", irradianceAtHit, "irradiance at the first opaque surface hit");
    addRealOption(t, "-dt", s.directThreshold, "direct threshold (fewer shadow rays to weaker sources)");
    addRealOption(t, "-dc", s.directCertainty, "direct certainty");
    addRealOption(t, "-dj", s.sourceJitter, "direct jitter (sources are sampled stratified)");
    addRealOption(t, "-ds", s.sourceSubdivision, "direct sampling: source size/distance ratio per shadow ray");
    addIntOption(t, "-dr", s.directRelays, "direct relays: sources seen in flat mirrors (one relay)");
    addIntOption(t, "-dp", s.directPresamples, "direct pretest density");
    t.addBool("-dv", s.directVisible, "light sources visible");
    addRealOption(t, "-ss", s.specularJitter, "specular sampling");
    addRealOption(t, "-st", s.materials.specularThreshold, "specular threshold: sampled rays above it");
    addColor(t, "-av", s.ambientValue, "ambient value beyond the last bounce");
    addIntOption(t, "-aw", s.ambientWeight, "ambient value weight");
    addIntOption(t, "-ab", s.ambientBounces,
                 "ambient bounces (diffuse interreflections; with the cache, -aa > 0, past them by Russian roulette "
                 "unless -al+ or -av is given)");
    t.addBool("-aP", s.skyPortals, "ambient portals: diffuse paths aim at the sky through windows too (Brume's)");
    t.addBool("-al", s.ambientLimit, "ambient limit: with the cache too, no light past -ab bounces (Radiance's)");
    addRealOption(t, "-aa", s.ambientAccuracy, "ambient accuracy: the irradiance cache's relative error (0: path tracing)");
    addIntOption(t, "-ar", s.ambientResolution, "ambient resolution");
    addIntOption(t, "-ad", s.ambientDivisions, "ambient divisions: paths at the first bounce");
    addIntOption(t, "-as", s.ambientSupersamples, "ambient super-samples");
    addRealOption(t, "-am", s.photonSearchRadius, "photon search radius");
    t.add("-acache", 1, "irradiance cache records: adaptive (Brume's) or classic (Ward-Heckbert's)",
          [&s](const auto& a) {
              if (a[0] == "adaptive") s.cacheKind = RecordShape::Kind::Adaptive;
              else if (a[0] == "classic") s.cacheKind = RecordShape::Kind::Classic;
              else throw Error("-acache: '" + a[0] + "' is neither adaptive nor classic");
          },
          [&s] { return std::string(s.cacheKind == RecordShape::Kind::Classic ? "classic" : "adaptive"); });
    addRealOption(t, "-at", s.recordLifetime,
                  "ambient time: the longest window of instants an irradiance cache record serves (s; 0: its own "
                  "instant alone; Brume's)");
    t.add("-af", 1, "irradiance cache file (Brume's format): records kept between runs and shared",
          [&s](const auto& a) { s.cacheFile = a[0]; });
    t.addUnsupported("-ae", 1, "ambient exclude modifier");
    t.addUnsupported("-ai", 1, "ambient include modifier");
    t.addUnsupported("-aE", 1, "ambient exclude file");
    t.addUnsupported("-aI", 1, "ambient include file");
    addColor(t, "-me", s.medium.extinction, "global medium extinction coefficient (1/world unit)");
    addColor(t, "-ma", s.medium.albedo, "global medium scattering albedo");
    addRealOption(t, "-mg", s.medium.g, "global medium scattering eccentricity (Henyey-Greenstein g)");
    addRealOption(t, "-ms", s.mediumSampling, "medium sampling distance: in-scattering samples along a ray");
    addIntOption(t, "-mc", s.majorantCell, "smoke majorant cell size in voxels (0: one cell, no empty-space skipping)");
    addIntOption(t, "-cs", s.sampling.channels, "spectral samples (3: RGB; up to 96 bands)");
    t.add("-cw", 2, "spectral range (nm)",
          [&s](const auto& a) { s.sampling.shortest = toReal("-cw", a[0]), s.sampling.longest = toReal("-cw", a[1]); },
          [&s] { return formatReal(s.sampling.shortest) + " " + formatReal(s.sampling.longest); });
    t.add("-T", 1, "scene time (s) for time-varying content", [&s](const auto& a) { s.time = toReal("-T", a[0]); },
          [&s] { return s.time ? formatReal(*s.time) : std::string(); });
    addIntOption(t, "-lr", s.maxReflections, "limit reflections (< 0: Russian roulette past |lr|)");
    addRealOption(t, "-lw", s.minWeight, "limit weight (Russian roulette below it)");
    // Radiance's options that Brume has no use for, accepted so that its command lines run unchanged.
    t.changeNothing({"-dc", "-dj", "-dp", "-ss", "-aw", "-as", "-am"});
}

void addColorOutputOptions(OptionTable& t, ColorOutput& o, bool values) {
    using Kind = ColorOutput::Kind;
    std::string kinds = values ? "RGB, XYZ, Y (photopic), S (scotopic), M (melanopic), MD65 (melanopic EDI), A (mean)"
                               : "RGB or XYZ";
    static const std::pair<const char*, Kind> names[] = {
        {"RGB", Kind::Rgb},       {"XYZ", Kind::Xyz},   {"Y", Kind::Photopic}, {"S", Kind::Scotopic},
        {"M", Kind::Melanopic}, {"MD65", Kind::MelanopicDaylight}, {"A", Kind::Mean}};
    t.addAttached("-p", "output: " + kinds, [&o, values](const std::string& v) {
        for (auto [name, kind] : names)
            if (v == name && (values || kind == Kind::Rgb || kind == Kind::Xyz)) {
                o.kind = kind, o.primaries = kRadiancePrimaries;
                return;
            }
        throw Error("bad output option -p" + v + " (" + (values ? "-pRGB, -pXYZ, -pY, -pS, -pM, -pMD65, -pA" : "-pRGB, -pXYZ") + ")");
    }, [&o] {
        for (auto [name, kind] : names)
            if (kind == o.kind) return std::string(name);
        return std::string("RGB");  // spectral output: -co says so
    });
    t.add("-pc", 8, "output primaries: xr yr xg yg xb yb xw yw", [&o](const auto& a) {
        std::array<double, 8> v, radiance = coordinates(kRadiancePrimaries);
        bool standard = true;  // within Radiance's tolerance of its own
        for (size_t i = 0; i < 8; ++i) {
            v[i] = toReal("-pc", a[i]);
            standard = standard && std::abs(v[i] - radiance[i]) <= .001;
        }
        Primaries p = primariesOf(v);
        if (!standard && !validPrimaries(p)) throw Error("illegal primary chromaticities");
        o.kind = Kind::Rgb, o.primaries = standard ? kRadiancePrimaries : p;
    }, [&o] {
        std::string text;
        for (double v : coordinates(o.primaries)) text += (text.empty() ? "" : " ") + formatReal(v);
        return text;
    });
    if (!values) return;
    t.addAttached("-co", "spectral output: every band (with -cs 3, RGB)", [&o](const std::string& v) {
        bool on = v.empty() ? o.kind != Kind::Spectral : v == "+" || v == "1";
        if (!on && !v.empty() && v != "-" && v != "0") throw Error("bad value '" + v + "' for option -co");
        if (on) o.kind = Kind::Spectral;
        else if (o.kind == Kind::Spectral) o.kind = Kind::Rgb;
    }, [&o] { return std::string(o.kind == Kind::Spectral ? "+" : "-"); });
}

void usePictureDefaults(RenderSettings& s) {
    s.directThreshold = .05, s.directCertainty = .5, s.sourceSubdivision = .25;
    s.directRelays = 1, s.materials.specularThreshold = .15;
    s.ambientAccuracy = .2, s.ambientResolution = 64, s.ambientDivisions = 512;
    s.ambientSupersamples = 128, s.maxReflections = 7, s.randomSampling = false;
}

void addProgramOptions(OptionTable& t, ProgramOptions& o) {
    o.threads = int(std::max(1u, std::thread::hardware_concurrency()));
    t.addBool("-w", o.warnings, "warning messages");
    t.add("-n", 1, "number of threads", [&o](const auto& a) {
        o.threads = toInt("-n", a[0]);
        if (o.threads <= 0) throw Error("bad number of processes");
    }, [&o] { return std::to_string(o.threads); });
    t.add("-e", 1, "error file (append)", [](const auto& a) {
        if (a[0].find_first_of("=:") != std::string::npos)
            throw Error("-e expressions (.cal) are not supported by Brume yet");
        if (!std::freopen(a[0].c_str(), "a", stderr)) throw Error("cannot open error file '" + a[0] + "'");
    });
    for (const char* name : {"-defaults", "-help", "-version", "-features"})
        t.add(name, 0, "print and exit", [&o, name](const auto&) { o.immediate = name; });
}

std::optional<CommandLine> parseCommandLine(int argc, char** argv, const OptionTable& table, const ProgramOptions& o,
                                            const std::string& usage, const std::string& features) {
    setProgramName(argv[0]);
    std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && args[0] == "--help") args[0] = "-help";
    size_t first = table.parse(args);
    setWarningsEnabled(o.warnings);
    if (o.immediate == "-help") std::cout << usage << table.usage();
    else if (o.immediate == "-version") std::printf("Brume %s\n", BRUME_VERSION);
    else if (o.immediate == "-defaults") std::fputs(table.defaults().c_str(), stdout);
    else if (o.immediate == "-features") std::fputs(features.c_str(), stdout);
    if (!o.immediate.empty()) return std::nullopt;
    if (first >= args.size()) {
        std::cerr << usage << table.usage();
        throw Error("missing octree or scene file argument");
    }
    CommandLine c;
    c.command.push_back(programName());
    c.command.insert(c.command.end(), args.begin(), args.begin() + first);
    c.scene.assign(args.begin() + first, args.end());
    return c;
}

void checkRenderSettings(const RenderSettings& s) {
    const HomogeneousMedium& m = s.medium;
    for (int i = 0; i < 3; ++i) {
        if (!(m.extinction[i] >= 0)) throw Error("-me: extinction coefficients must be positive or 0");
        if (!(m.albedo[i] >= 0 && m.albedo[i] <= 1)) throw Error("-ma: albedo must be between 0 and 1");
    }
    if (!(std::abs(m.g) < 1)) throw Error("-mg: eccentricity must be between -1 and 1");
    if (!(s.mediumSampling >= 0)) throw Error("-ms: sampling distance must be positive or 0");
    if (s.majorantCell < 0) throw Error("-mc: majorant cell size must be positive or 0");
    if (!(s.recordLifetime >= 0 && std::isfinite(s.recordLifetime)))
        throw Error("-at: the longest window of time must be finite and positive or 0");
    if (s.maxReflections <= 0 && !(s.minWeight > 0))
        throw Error("-lw must be positive when -lr is 0 or negative (Russian roulette needs it)");
}

std::string cacheOptions(const RenderSettings& settings) {
    RenderSettings copy = settings;
    bool irradianceAtHit = false;
    OptionTable table;
    addRenderOptions(table, copy, irradianceAtHit);
    std::string text = "brume-" BRUME_VERSION;
    for (const std::string& option : table.valueOptions()) {
        // Which surface a value is asked for (-i), how samples are seeded (-u) and the instant (-T, which
        // each record keeps) change no record.
        if (option.rfind("-i", 0) == 0 || option.rfind("-u", 0) == 0 || option.rfind("-af", 0) == 0 ||
            option.rfind("-T", 0) == 0)
            continue;
        text += " " + option;
    }
    return text;
}

}  // namespace brume
