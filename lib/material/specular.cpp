#include "material/specular.h"
#include "spectrum/rgb_to_spectrum.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace brume {

namespace {

void expectReals(const SceneObject& o, size_t lo, size_t hi, size_t maxStrings = 0) {
    if (o.strings.size() > maxStrings || !o.integers.empty() || o.reals.size() < lo || o.reals.size() > hi)
        throw Error(o.where, "bad arguments for " + o.type + " \"" + o.name + "\"");
}

Spectrum rgb(const SceneObject& o) { return spectrumFromRgb(o.reals[0], o.reals[1], o.reals[2]); }

// Unpolarised Fresnel reflectance for cosines c1 (outside) and c2 (inside) and relative index n,
// as the mean of the s and p terms.
void fresnelTerms(double c1, double c2, double n, double& rs, double& rp) {
    rs = (c1 - n * c2) / (c1 + n * c2);
    rs *= rs;
    rp = (1 / c1 - n / c2) / (1 / c1 + n / c2);
    rp *= rp;
}

}  // namespace

Mirror::Mirror(const SceneObject& o, const MaterialSettings& settings)
    : color_(0.f), backVisible_(settings.backVisible) {
    expectReals(o, 3, 3, 1);
    if (!o.strings.empty() && o.strings[0] != "void")
        warn(o.where.str() + ": mirror \"" + o.name + "\": alternate material not supported yet, ignored");
    color_ = rgb(o);
}

bool Mirror::scatter(const Shading& s, Lobes& lobes) const {
    if (s.backside) return backVisible_;  // black from behind, or invisible
    lobes.addDelta(s.dir + 2 * s.cosine * s.normal, color_ * s.pattern, false);
    return true;
}

Glass::Glass(const SceneObject& o, const MaterialSettings& settings)
    : color_(0.f), backVisible_(settings.backVisible) {
    expectReals(o, 3, 4);
    color_ = rgb(o);
    index_ = o.reals.size() == 4 ? o.reals[3] : 1.52;
    if (!(index_ > 0)) throw Error(o.where, "bad refractive index for glass \"" + o.name + "\"");
}

// Reflection and transmission of a pane with incoherent multiple reflections between its two faces,
// averaged over both polarisations (Radiance reference manual, glass).
void Glass::coefficients(double c1, Spectrum& reflect, Spectrum& transmit) const {
    double n = index_;
    double c2 = std::sqrt(1 - 1 / (n * n) + c1 * c1 / (n * n));
    double rs, rp;
    fresnelTerms(c1, c2, n, rs, rp);
    reflect = transmit = color_;
    for (int i = 0; i < color_.size(); ++i) {
        double tau = std::pow(std::max<double>(color_[i], 1e-15), 1 / c2);
        double t2 = tau * tau;
        transmit[i] = float(0.5 * (1 - rs) * (1 - rs) * tau / (1 - rs * rs * t2) +
                            0.5 * (1 - rp) * (1 - rp) * tau / (1 - rp * rp * t2));
        reflect[i] = float(0.5 * rs * (1 + (1 - 2 * rs) * t2) / (1 - rs * rs * t2) +
                           0.5 * rp * (1 + (1 - 2 * rp) * t2) / (1 - rp * rp * t2));
    }
}

bool Glass::scatter(const Shading& s, Lobes& lobes) const {
    if (s.backside && !backVisible_) return false;
    Spectrum reflect, transmit;
    coefficients(s.cosine, reflect, transmit);
    lobes.addDelta(s.dir, transmit * s.pattern, true);
    lobes.addDelta(s.dir + 2 * s.cosine * s.normal, reflect, false);
    return true;
}

Spectrum Glass::shadowTransmission(const Shading& s, dvec3& dir) const {
    Spectrum reflect, transmit;
    coefficients(s.cosine, reflect, transmit);
    return transmit * s.pattern;
}

Dielectric::Dielectric(const SceneObject& o) : color_(0.f) {
    expectReals(o, 5, 5);
    color_ = rgb(o);
    index_ = o.reals[3] + o.reals[4] / 500;  // Hartmann's formula at 500 nm
    if (!(index_ > 0)) throw Error(o.where, "bad refractive index for dielectric \"" + o.name + "\"");
}

double Dielectric::fresnel(const Shading& s, dvec3& refractedDir, double& ratio, bool& refracted) const {
    ratio = s.backside ? index_ : 1 / index_;
    double c1 = s.cosine;
    double d = 1 - ratio * ratio * (1 - c1 * c1);
    refracted = d > 1e-6;
    if (!refracted) return 1;
    double c2 = std::sqrt(d);
    double rs, rp;
    fresnelTerms(c1, c2, ratio, rs, rp);
    refractedDir = glm::normalize(ratio * s.dir + (ratio * c1 - c2) * s.normal);
    return 0.5 * (rs + rp);
}

bool Dielectric::scatter(const Shading& s, Lobes& lobes) const {
    // A ray arriving from inside has crossed the medium: it lost color^distance on the way.
    if (s.backside)
        for (int i = 0; i < color_.size(); ++i)
            lobes.incomingAttenuation[i] = float(std::pow(std::max<double>(color_[i] * s.pattern[i], 0), s.distance));
    dvec3 refractedDir;
    double ratio;
    bool refracted;
    double r = fresnel(s, refractedDir, ratio, refracted);
    // Radiance is compressed into a smaller solid angle on entering a denser medium (n² law).
    if (refracted) lobes.addDelta(refractedDir, Spectrum(float((1 - r) * ratio * ratio)), true);
    lobes.addDelta(s.dir + 2 * s.cosine * s.normal, Spectrum(float(r)), false);
    return true;
}

Spectrum Dielectric::shadowTransmission(const Shading& s, dvec3& dir) const {
    dvec3 refractedDir;
    double ratio;
    bool refracted;
    double r = fresnel(s, refractedDir, ratio, refracted);
    if (!refracted) return Spectrum(0.f);
    dir = refractedDir;
    Spectrum t(float((1 - r) * ratio * ratio));
    if (s.backside)
        for (int i = 0; i < color_.size(); ++i)
            t[i] *= float(std::pow(std::max<double>(color_[i] * s.pattern[i], 0), s.distance));
    return t;
}

}  // namespace brume
