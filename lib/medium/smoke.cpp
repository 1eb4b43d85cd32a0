#include "medium/smoke.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <span>

#include <glm/matrix.hpp>

#include "scene/raypath.h"
#include "spectrum/binned_spectrum.h"
#include "spectrum/colorimetry.h"
#include "spectrum/rgb_to_spectrum.h"
#include "util/options.h"

namespace brume {

namespace {

[[noreturn]] void badSmoke(const SceneObject& o, const std::string& why) {
    throw Error(o.where, "bad smoke '" + o.name + "': " + why);
}

DensityGrid loadGrid(const SceneObject& o, const std::string& name, const std::string& gridName) {
    const std::string path = findOnRayPath(name);
    if (path.empty()) badSmoke(o, "cannot find VDB file \"" + name + "\"");
    try {
        return DensityGrid(path, gridName);
    } catch (const Error& e) {
        badSmoke(o, e.what());
    }
}

double keyFrameTime(const SceneObject& o, const std::string& word) {
    double t = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), t);
    if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(t))
        badSmoke(o, "bad key-frame time '" + word + "'");
    return t;
}

// The key frames of grid `gridName` in the files the strings name after their keywords: one file (static
// smoke), or pairs of a time and a file.
std::shared_ptr<const GridSequence> readFrames(const SceneObject& o, std::span<const std::string> words,
                                               const std::string& gridName) {
    if (words.empty() || (words.size() > 1 && words.size() % 2 != 0))
        badSmoke(o, "expected [density=NAME] [temperature=NAME] [extinction=soot] then one file, or key frames as time and file pairs");
    std::vector<KeyFrame> frames;
    if (words.size() == 1) frames.push_back({0, loadGrid(o, words[0], gridName)});
    else
        for (std::size_t i = 0; i < words.size(); i += 2)
            frames.push_back({keyFrameTime(o, words[i]), loadGrid(o, words[i + 1], gridName)});
    try {
        return std::make_shared<const GridSequence>(std::move(frames));
    } catch (const Error& e) {
        badSmoke(o, e.what());
    }
}

// Cells twice a voxel wide over where both the density and the temperature may be non-zero, weighed by the
// brightness of what the smoke emits.
EmissionCells flameCells(const SmokeVolume& smoke, const SmokeDescription& d) {
    Bounds3 box = d.frames->bounds(), hot = d.temperature->bounds();
    box.lo = glm::max(box.lo, hot.lo), box.hi = glm::min(box.hi, hot.hi);
    const glm::dmat4 m = d.frames->keyFrames().front().grid.voxels().worldFromIndex();
    double voxel = std::cbrt(std::abs(glm::determinant(glm::dmat3(m))));
    return EmissionCells(box, 2 * voxel, [&](const dvec3& p) { return double(brightness(smoke.emission(p))); });
}

}  // namespace

Spectrum sootExtinction() {
    constexpr double kFirst = 360, kLast = 830;
    std::vector<double> bins;  // 1 nm bins centred on whole nanometres
    for (double nm = kFirst; nm <= kLast; nm += 1) bins.push_back(std::pow(nm / 633, -1.39));
    return spectrumFromBins(bins, kFirst - 0.5, kLast + 0.5);
}

SmokeDescription readSmoke(const SceneObject& o) {
    if (!o.integers.empty()) badSmoke(o, "expected no integers");
    const std::vector<double>& r = o.reals;
    if (r.size() != 3 && r.size() != 6 && r.size() != 7) badSmoke(o, "expected 3, 6 or 7 reals");
    if (r[0] < 0 || r[1] < 0 || r[2] < 0) badSmoke(o, "extinction per unit density must not be negative");
    for (std::size_t i = 3; i < 6 && i < r.size(); ++i)
        if (!(r[i] >= 0 && r[i] <= 1)) badSmoke(o, "albedo must be between 0 and 1");
    const double g = r.size() == 7 ? r[6] : 0;
    if (!(std::abs(g) < 1)) badSmoke(o, "g must be strictly between -1 and 1");
    SmokeDescription smoke;
    smoke.where = o.where;
    smoke.name = o.name;
    smoke.extinctionPerDensity = spectrumFromRgb(r[0], r[1], r[2]);
    smoke.albedo = r.size() >= 6 ? spectrumFromRgb(r[3], r[4], r[5]) : Spectrum(0.f);
    smoke.g = g;
    // Last: the arguments are checked before any file is read.
    std::span<const std::string> words = o.strings;
    std::string density = "density", temperature, extinction;
    for (; !words.empty() && words[0].find('=') != std::string::npos; words = words.subspan(1)) {
        const std::string& w = words[0];
        std::string value = w.substr(w.find('=') + 1);
        if (w.starts_with("extinction=")) {
            if (value != "soot" && value != "grey") badSmoke(o, "unknown extinction '" + value + "' (soot, grey)");
            extinction = value;
            continue;
        }
        if (w.starts_with("density=")) density = value;
        else if (w.starts_with("temperature=")) temperature = value;
        else badSmoke(o, "unknown keyword '" + w + "' (density=, temperature=, extinction=)");
        if (value.empty()) badSmoke(o, "empty grid name in '" + w + "'");
    }
    if (extinction == "soot") {
        if (r[1] != r[0] || r[2] != r[0]) badSmoke(o, "extinction=soot takes one K, at 633 nm: the three must be equal");
        smoke.extinctionAt633 = r[0];
        smoke.extinctionPerDensity = sootExtinction() * float(r[0]);
    }
    smoke.frames = readFrames(o, words, density);
    if (!temperature.empty()) smoke.temperature = readFrames(o, words, temperature);
    return smoke;
}

void checkInstants(const std::vector<SmokeDescription>& smoke, std::span<const double> times) {
    for (const SmokeDescription& s : smoke) {
        const std::vector<KeyFrame>& frames = s.frames->keyFrames();
        if (frames.size() < 2) continue;  // static
        for (double t : times)
            if (!(t >= frames.front().time && t <= frames.back().time))
                throw Error(s.where, "smoke '" + s.name + "': no data at " + formatShort(t) + " s, outside its " +
                                         std::to_string(frames.size()) + " key frames (" +
                                         formatShort(frames.front().time) + " to " + formatShort(frames.back().time) +
                                         " s; -T sets the instant)");
    }
}

std::string dataNote(const SmokeDescription& smoke) {
    for (const KeyFrame& f : smoke.frames->keyFrames())
        if (!f.grid.coverage().note().empty()) return f.grid.coverage().note();
    return "";
}

std::vector<std::string> noDataWarnings(const std::vector<SmokeDescription>& smoke) {
    std::vector<std::string> out;
    for (const SmokeDescription& s : smoke) {
        const std::vector<KeyFrame>& frames = s.frames->keyFrames();
        if (std::none_of(frames.begin(), frames.end(), [](const KeyFrame& f) { return f.grid.coverage().incomplete(); }))
            continue;
        const std::string note = dataNote(s);
        out.push_back(s.where.str() + ": smoke '" + s.name + "': part of its simulation's domain has no data" +
                      (note.empty() ? "" : " (" + note + ")") +
                      ": rays cross it as clear air (vismap flags sight lines through it)");
    }
    return out;
}

SmokeVolume::SmokeVolume(const SmokeDescription& smoke, double time, int voxelsPerCell)
    : description_(smoke),
      time_(time),
      majorant_(smoke.frames->boundsAt(time, voxelsPerCell)),
      bounds_(smoke.frames->bounds()),
      // One float ulp above the largest band: extinction() rounds K·ρ to float, which may exceed K·ρ by
      // half an ulp, and the majorant must still bound it.
      scale_(smoke.extinctionPerDensity.maxValue() * (1 + 0x1p-23)),
      scaleDown_(smoke.extinctionPerDensity.maxValue() * (1 - 0x1p-23)) {
    checkInstants({smoke}, {&time, 1});
    if (emits()) {
        blackbodies_ = std::make_shared<const BlackbodyTable>();
        flames_ = flameCells(*this, description_);
    }
}

double SmokeVolume::quotedExtinctionPerDensity(QuotedExtinction quoted) const {
    if (quoted == QuotedExtinction::At633nm && description_.extinctionAt633) return *description_.extinctionAt633;
    return photopic(description_.extinctionPerDensity);
}

double SmokeVolume::density(const dvec3& p) const { return description_.frames->density(p, time_); }

Spectrum SmokeVolume::emission(const dvec3& p, double density) const {
    return blackbodies_->at(description_.temperature->density(p, time_)) * description_.extinctionPerDensity *
           float(density) * (Spectrum(1.f) - description_.albedo);
}

// Consecutive cells of uneven smoke make one run: one walk through the voxels.
template <class Even, class Uneven>
void SmokeVolume::forEachRun(const Ray& ray, double tmin, double tmax, Even&& even, Uneven&& uneven) const {
    double unevenFrom = tmin, unevenTo = tmin;
    auto flush = [&] {
        if (unevenTo > unevenFrom) uneven(unevenFrom, unevenTo);
    };
    majorant_.forEachBound(ray, tmin, tmax, [&](double t0, double t1, double majorant, double minorant) {
        if (majorant > minorant) {
            if (t0 != unevenTo) flush(), unevenFrom = t0;
            unevenTo = t1;
            return true;
        }
        even(t0, t1, majorant);  // even smoke, or none
        return true;
    });
    flush();
}

double SmokeVolume::densityIntegral(const Ray& ray, double tmin, double tmax) const {
    double sum = 0;
    forEachRun(
        ray, tmin, tmax, [&](double t0, double t1, double density) { sum += density * (t1 - t0); },
        [&](double t0, double t1) { sum += description_.frames->integral(ray, t0, t1, time_); });
    return sum;
}

Spectrum SmokeVolume::transmittance(const Ray& ray, double tmin, double tmax) const {
    return transmittance(densityIntegral(ray, tmin, tmax));
}

Spectrum SmokeVolume::transmittance(double integral) const {
    const Spectrum& k = description_.extinctionPerDensity;
    Spectrum t(1.f, k.size());
    for (int i = 0; i < t.size(); ++i) t[i] = float(std::exp(-double(k[i]) * integral));
    return t;
}

DensityProfile SmokeVolume::profile(const Ray& ray, double tmin, double tmax) const {
    DensityProfile out;
    forEachRun(
        ray, tmin, tmax, [&](double t0, double t1, double density) { out.append(t0, t1, density); },
        [&](double t0, double t1) { out.append(description_.frames->profile(ray, t0, t1, time_)); });
    return out;
}

}  // namespace brume
