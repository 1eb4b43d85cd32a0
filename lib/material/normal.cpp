// plastic, metal and trans: Radiance's "normal" materials (reference manual §"Plastic", "Metal",
// "Trans"; the split of reflectances follows Radiance's normal.c semantics).
#include "material/normal.h"
#include "spectrum/rgb_to_spectrum.h"

namespace brume {

namespace {
constexpr double kTiny = 1e-6;
}

NormalMaterial::NormalMaterial(const SceneObject& o, const MaterialSettings& settings) : settings_(settings) {
    kind_ = o.type == "metal" ? Kind::Metal : o.type == "trans" ? Kind::Trans : Kind::Plastic;
    size_t want = kind_ == Kind::Trans ? 7 : 5;
    if (!o.strings.empty() || !o.integers.empty() || o.reals.size() != want)
        throw Error(o.where, "bad arguments for " + o.type + " \"" + o.name + "\": expected 0 strings, 0 integers, " +
                                 std::to_string(want) + " reals");
    color_ = spectrumFromRgb(o.reals[0], o.reals[1], o.reals[2]);
    spec_ = o.reals[3];
    alpha2_ = o.reals[4] * o.reals[4];
    if (kind_ == Kind::Trans) trans_ = o.reals[5], transSpec_ = o.reals[6];
}

bool NormalMaterial::pure() const { return alpha2_ <= kTiny; }

// The specular reflectance at this view cosine: pure specular surfaces brighten toward grazing angles.
double NormalMaterial::specular(double cosine, double& fresnel) const {
    fresnel = pure() && spec_ >= 0.017999 ? fresnelEstimate(cosine) : 0.0;
    return spec_ + fresnel * (1 - spec_);
}

bool NormalMaterial::scatter(const Shading& s, Lobes& lobes) const {
    if (s.backside && !settings_.backVisible) return false;
    double fresnel;
    double rspec = specular(s.cosine, fresnel);
    double transmitted = trans_ * (1 - rspec);
    double tspec = transmitted * transSpec_;
    double tdiff = transmitted - tspec;
    double rdiff = 1 - transmitted - rspec;
    Spectrum color = color_ * s.pattern;
    Spectrum scolor{float(rspec)};
    if (kind_ == Kind::Metal) {
        scolor = color * float(rspec);
        if (fresnel > kTiny)
            for (int i = 0; i < scolor.size(); ++i) scolor[i] = float(fresnel + color[i] * spec_ * (1 - fresnel));
    }
    lobes.diffuse = color * float(rdiff);
    lobes.diffuseTrans = color * float(tdiff);
    lobes.ambient = lobes.diffuse;
    lobes.ambientTrans = lobes.diffuseTrans;
    if (pure()) {
        // Radiance reduces the diffuse part per source whenever the pure specular part is not negligible.
        lobes.fresnelDiffuse = rspec >= 0.017999;
        if (rspec > kTiny) lobes.addDelta(s.dir + 2 * s.cosine * s.normal, scolor, false);
        if (tspec > kTiny) lobes.addDelta(s.dir, color * float(tspec), true);
        return true;
    }
    if (rspec > kTiny) {
        lobes.glossy = scolor;
        lobes.alpha2 = alpha2_;
        lobes.sampleGlossy = rspec > settings_.specularThreshold + kTiny;
        if (!lobes.sampleGlossy) lobes.ambient += scolor;
    }
    if (tspec > kTiny) {
        lobes.glossyTrans = color * float(tspec);
        lobes.alphaT2 = alpha2_;
        lobes.sampleGlossyTrans = tspec > settings_.specularThreshold + kTiny;
        if (!lobes.sampleGlossyTrans) lobes.ambientTrans = color * float(transmitted);
    }
    return true;
}

// Only the pure specular transmission of trans lets direct light through; rough trans blocks it.
Spectrum NormalMaterial::shadowTransmission(const Shading& s, dvec3& dir) const {
    if (kind_ != Kind::Trans || !pure()) return Spectrum(0.f);
    double fresnel;
    double rspec = specular(s.cosine, fresnel);
    return color_ * s.pattern * float(trans_ * (1 - rspec) * transSpec_);
}

}  // namespace brume
