#include "material/anisotropic.h"

#include "sampling/warp.h"
#include "spectrum/rgb_to_spectrum.h"
#include "util/error.h"

namespace brume {

namespace {
constexpr double kTiny = 1e-6;  // Radiance's FTINY
}

AnisotropicMaterial::AnisotropicMaterial(const SceneObject& o, const MaterialSettings& settings,
                                         PatternLibrary& functions)
    : settings_(settings), metal_(o.type == "metal2"), where_(o.where.str()), color_(0.f) {
    size_t want = o.type == "trans2" ? 8 : 6;
    if (o.reals.size() != want)
        badArguments(o, "expected " + std::to_string(want) + " real arguments, got " + std::to_string(o.reals.size()));
    if (o.reals[4] <= kTiny || o.reals[5] <= kTiny) badArguments(o, "roughness too small");
    orientation_ = functionObject(o, functions, 3, 0, 3);
    color_ = spectrumFromRgb(o.reals[0], o.reals[1], o.reals[2]);
    spec_ = o.reals[3];
    au2_ = o.reals[4] * o.reals[4];
    av2_ = o.reals[5] * o.reals[5];
    if (want == 8) {
        trans_ = o.reals[6] * (1 - spec_);
        tspec_ = trans_ * o.reals[7];
    }
}

bool AnisotropicMaterial::scatter(const Shading& s, Lobes& lobes) const {
    if (s.backside && !settings_.backVisible) return false;
    Spectrum color = color_ * s.pattern;
    Spectrum reflect = metal_ ? color * float(spec_) : Spectrum(float(spec_));
    lobes.diffuse = color * float(1 - trans_ - spec_);
    lobes.diffuseTrans = color * float(trans_ - tspec_);
    lobes.ambient = lobes.diffuse;
    lobes.ambientTrans = lobes.diffuseTrans;
    // Specular parts at or below -st are blurred into the ambient, as Radiance does; above it they are traced.
    bool reflects = spec_ > kTiny, transmits = tspec_ > kTiny;
    bool traceReflection = reflects && spec_ > settings_.specularThreshold + kTiny;
    bool traceTransmission = transmits && tspec_ > settings_.specularThreshold + kTiny;
    if (reflects && !traceReflection) lobes.ambient += reflect;
    if (transmits && !traceTransmission) lobes.ambientTrans = color * float(trans_);
    if (reflects || transmits) lobes.general = this;
    lobes.sampleGeneral = traceReflection || traceTransmission;
    return true;
}

// Radiance's getacoords: u from the function file, made perpendicular to the normal. A u along the normal
// leaves no orientation: the lobe becomes isotropic with the mean squared roughness.
AnisoFrame AnisotropicMaterial::frame(const Shading& s) const {
    cal::Evaluator& eval = orientation_.begin(*s.hit, *s.evaluator);
    dvec3 u(eval(orientation_.exprs[0]), eval(orientation_.exprs[1]), eval(orientation_.exprs[2]));
    u = orientation_.frame.toWorldVector(u, *s.hit);
    dvec3 v = glm::cross(s.normal, u);
    double length = glm::length(v);
    if (length > 1e-9 * glm::length(u)) {
        v /= length;
        return AnisoFrame{s.normal, glm::cross(v, s.normal), v, au2_, av2_};
    }
    if (std::abs(std::sqrt(au2_) - std::sqrt(av2_)) > 0.001) warnOnce(where_ + ": illegal orientation vector");
    Frame f(s.normal);
    double mean = 0.5 * (au2_ + av2_);
    return AnisoFrame{s.normal, f.s, f.t, mean, mean};
}

AnisotropicMaterial::At AnisotropicMaterial::at(const Shading& s) const {
    At a{frame(s), Spectrum(0.f), Spectrum(0.f)};
    Spectrum color = color_ * s.pattern;
    if (spec_ > kTiny) a.reflect = metal_ ? color * float(spec_) : Spectrum(float(spec_));
    if (tspec_ > kTiny) a.transmit = color * float(tspec_);
    double r = spec_ > settings_.specularThreshold + kTiny ? brightness(a.reflect) : 0.0;
    double t = tspec_ > settings_.specularThreshold + kTiny ? brightness(a.transmit) : 0.0;
    if (r + t > 0) a.reflectShare = r / (r + t), a.transmitShare = t / (r + t);
    return a;
}

// Radiance's diraniso, without its widening of the lobe by the source's solid angle (Brume integrates over
// the source instead).
Spectrum AnisotropicMaterial::response(const Shading& s, const At& a, const dvec3& wi) const {
    double cosL = glm::dot(s.normal, wi);
    if (cosL > kTiny && !a.reflect.isBlack())
        return a.reflect * float(anisoWardBrdf(a.frame, -s.dir, wi) * cosL);
    if (cosL < -kTiny && !a.transmit.isBlack())
        return a.transmit * float(anisoTransmission(a.frame, s.dir, std::max(s.cosine, 0.001), wi));
    return Spectrum(0.f);
}

double AnisotropicMaterial::pdf(const Shading& s, const At& a, const dvec3& wi) const {
    if (glm::dot(s.normal, wi) > 0) return a.reflectShare * anisoWardPdf(a.frame, -s.dir, wi);
    return a.transmitShare * anisoTransmissionPdf(a.frame, s.dir, std::max(s.cosine, 0.001), wi);
}

Spectrum AnisotropicMaterial::response(const Shading& s, const dvec3& wi) const { return response(s, at(s), wi); }

double AnisotropicMaterial::pdf(const Shading& s, const dvec3& wi) const { return pdf(s, at(s), wi); }

// One of the traced parts, chosen by its brightness; draws that leave the part's side are lost (Radiance
// draws again instead).
std::optional<LobeSample> AnisotropicMaterial::sample(const Shading& s, double x, double y) const {
    At a = at(s);
    if (a.reflectShare + a.transmitShare <= 0) return std::nullopt;
    bool reflection = x < a.reflectShare;
    x = reflection ? x / a.reflectShare : (x - a.reflectShare) / a.transmitShare;
    dvec3 wi = reflection ? sampleAnisoWard(a.frame, -s.dir, x, y) : sampleAnisoTransmission(a.frame, s.dir, x, y);
    double cosL = glm::dot(s.normal, wi);
    if (reflection ? cosL <= kTiny : cosL >= -kTiny) return std::nullopt;
    double density = pdf(s, a, wi);
    if (!(density > 0)) return std::nullopt;
    return LobeSample{wi, response(s, a, wi) * float(1 / density), density, !reflection};
}

}  // namespace brume
