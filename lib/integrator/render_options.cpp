#include "integrator/render_options.h"

#include <cstdio>

namespace brume {

namespace {

std::string real(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%f", v);
    return buf;
}

void addInt(OptionTable& t, const std::string& name, int& v, const std::string& help) {
    t.add(name, 1, help, [&v, name](const auto& a) { v = toInt(name, a[0]); }, [&v] { return std::to_string(v); });
}

void addReal(OptionTable& t, const std::string& name, double& v, const std::string& help) {
    t.add(name, 1, help, [&v, name](const auto& a) { v = toReal(name, a[0]); }, [&v] { return real(v); });
}

void addColor(OptionTable& t, const std::string& name, Spectrum& v, const std::string& help) {
    t.add(name, 3, help,
          [&v, name](const auto& a) {
              v = Spectrum(float(toReal(name, a[0])), float(toReal(name, a[1])), float(toReal(name, a[2])));
          },
          [&v] { return real(v[0]) + " " + real(v[1]) + " " + real(v[2]); });
}

}  // namespace

void addRenderOptions(OptionTable& t, RenderSettings& s, bool& irradianceAtHit) {
    t.addBool("-u", s.randomSampling, "uncorrelated random sampling (- : reproducible, same result for any -n)");
    t.addBool("-bv", s.materials.backVisible, "back face visibility");
    t.addBool("-i", irradianceAtHit, "irradiance at the first opaque surface hit");
    addReal(t, "-dt", s.directThreshold, "direct threshold (every source sample is tested)");
    addReal(t, "-dc", s.directCertainty, "direct certainty");
    addReal(t, "-dj", s.sourceJitter, "direct jitter (sources are always sampled stratified)");
    addReal(t, "-ds", s.sourceSubdivision, "direct sampling: source size/distance ratio per shadow ray");
    addInt(t, "-dr", s.directRelays, "direct relays: sources seen in flat mirrors (one relay)");
    addInt(t, "-dp", s.directPresamples, "direct pretest density");
    t.addBool("-dv", s.directVisible, "light sources visible");
    addReal(t, "-ss", s.specularJitter, "specular sampling");
    addReal(t, "-st", s.materials.specularThreshold, "specular threshold: sampled rays above it");
    addColor(t, "-av", s.ambientValue, "ambient value beyond the last bounce");
    addInt(t, "-aw", s.ambientWeight, "ambient value weight");
    addInt(t, "-ab", s.ambientBounces, "ambient bounces (diffuse interreflections, exactly)");
    addReal(t, "-aa", s.ambientAccuracy, "ambient accuracy (0: path tracing; cache: later)");
    addInt(t, "-ar", s.ambientResolution, "ambient resolution");
    addInt(t, "-ad", s.ambientDivisions, "ambient divisions: paths at the first bounce");
    addInt(t, "-as", s.ambientSupersamples, "ambient super-samples");
    t.addUnsupported("-af", 1, "ambient cache file");
    t.addUnsupported("-ae", 1, "ambient exclude modifier");
    t.addUnsupported("-ai", 1, "ambient include modifier");
    t.addUnsupported("-aE", 1, "ambient exclude file");
    t.addUnsupported("-aI", 1, "ambient include file");
    t.addUnsupported("-me", 3, "mist extinction coefficient");
    t.addUnsupported("-ma", 3, "mist scattering albedo");
    t.addUnsupported("-mg", 1, "mist scattering eccentricity");
    t.addUnsupported("-ms", 1, "mist sampling distance");
    addInt(t, "-lr", s.maxReflections, "limit reflections (< 0: Russian roulette past |lr|)");
    addReal(t, "-lw", s.minWeight, "limit weight (Russian roulette below it)");
}

}  // namespace brume
