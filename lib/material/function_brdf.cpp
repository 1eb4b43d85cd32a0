#include "material/function_brdf.h"

#include "spectrum/colorimetry.h"
#include "spectrum/rgb_to_spectrum.h"
#include "util/error.h"

namespace brume {

namespace {
constexpr double kTiny = 1e-6;  // Radiance's FTINY
}

// Strings: func funcfile [transform], or func datafile funcfile v0 … [transform] (one coordinate function per
// dimension of the data). Reals: red green blue rspec (trans tspec for the trans types) A5 …
FunctionBrdfMaterial::FunctionBrdfMaterial(const SceneObject& o, const MaterialSettings& settings,
                                           PatternLibrary& functions)
    : backVisible_(settings.backVisible),
      metal_(o.type.starts_with("met")),
      transmits_(o.type.starts_with("trans")),
      color_(0.f) {
    bool data = o.type.ends_with("data");
    size_t reals = transmits_ ? 6 : 4;
    if (o.reals.size() < reals) badArguments(o, "expected at least " + std::to_string(reals) + " real arguments");
    f_ = functionObject(o, functions, data ? 2 : 1, 0, 0);
    if (data) {
        data_ = &functions.dataFile(o.strings[1]);
        size_t dims = size_t(data_->dimensions());
        if (o.strings.size() < 3 + dims) badArguments(o, "too few string arguments");
        for (size_t i = 0; i < dims; ++i) coordinates_.push_back(functions.function(o.strings[3 + i], 4, f_.scope, o.where));
    }
    brdf_ = functions.function(o.strings[0], data ? 5 : 4, f_.scope, o.where);
    color_ = spectrumFromRgb(o.reals[0], o.reals[1], o.reals[2]);
    rspec_ = o.reals[3];
    if (transmits_) {
        trans_ = o.reals[4] * (1 - rspec_);
        tspec_ = trans_ * o.reals[5];
    }
}

bool FunctionBrdfMaterial::scatter(const Shading& s, Lobes& lobes) const {
    if (s.backside && !backVisible_) return false;
    Spectrum color = color_ * s.pattern;
    lobes.diffuse = color * float(1 - trans_ - rspec_);
    lobes.diffuseTrans = color * float(trans_ - tspec_);
    // Radiance's ambient: the whole reflectance on each side, in the material's colour.
    if (trans_ < 1 - kTiny) lobes.ambient = color * float(1 - trans_);
    if (trans_ > kTiny) lobes.ambientTrans = color * float(trans_);
    lobes.general = this;
    return true;
}

// The function's variables as Radiance's setbrdfunc sets them: the ray's, then the perturbed normal
// (NxP …), its cosine (RdotP) and the material's colour with its patterns (CrP …).
double FunctionBrdfMaterial::value(const Shading& s, const dvec3& wi) const {
    PatternEvaluator& e = *s.evaluator;
    f_.frame.channels(*s.hit, e.channels);
    dvec3 n = f_.frame.toPatternDirection(s.normal, *s.hit);
    Color3 color = toRgb(color_ * s.pattern);  // RGB however many bands
    e.channels[cal::NxP] = n.x, e.channels[cal::NyP] = n.y, e.channels[cal::NzP] = n.z;
    e.channels[cal::RdotP] = s.cosine;
    e.channels[cal::CrP] = color[0], e.channels[cal::CgP] = color[1], e.channels[cal::CbP] = color[2];
    e.eval.begin(e.channels, f_.args);
    dvec3 l = f_.frame.toPatternDirection(wi, *s.hit);
    // The last argument is Radiance's source sample solid angle; Brume integrates over sources and gives 0.
    double args[5] = {0, l.x, l.y, l.z, 0};
    if (!data_) return e.eval(brdf_, std::span<const double>(args + 1, 4));
    double point[DataGrid::kMaxDimensions];
    for (size_t i = 0; i < coordinates_.size(); ++i) point[i] = e.eval(coordinates_[i], std::span<const double>(args + 1, 4));
    float v;
    data_->interpolate(std::span<const double>(point, coordinates_.size()), &v);
    args[0] = v;
    return e.eval(brdf_, std::span<const double>(args, 5));
}

// Radiance's dirbrdf, specular part: the function's value times the specular coefficient and the cosine,
// coloured by the material for metals' reflection and for transmission.
Spectrum FunctionBrdfMaterial::response(const Shading& s, const dvec3& wi) const {
    double cosL = glm::dot(s.normal, wi);
    bool reflected = cosL > 0;
    double coefficient = reflected ? rspec_ : tspec_;
    if (std::abs(cosL) <= kTiny || coefficient <= kTiny) return Spectrum(0.f);
    double f = value(s, wi);
    if (!(f > kTiny)) return Spectrum(0.f);
    Spectrum c = (reflected ? metal_ : transmits_) ? color_ * s.pattern : Spectrum(1.f);
    return c * float(f * coefficient * std::abs(cosL));
}

}  // namespace brume
