#include "material/bsdf_material.h"

#include <atomic>
#include <cmath>

#include "pattern/pattern_frame.h"
#include "pattern/pattern_library.h"
#include "scene/raypath.h"
#include "spectrum/rgb_to_spectrum.h"
#include "util/error.h"

namespace brume {

namespace {

constexpr double kTiny = 1e-6;  // Radiance's FTINY

[[noreturn]] void badArguments(const SceneObject& o, const std::string& why) {
    throw Error(o.where, "bad arguments for BSDF \"" + o.name + "\": " + why);
}

Spectrum spectrum(const Rgb& c) { return spectrumFromRgb(c[0], c[1], c[2]); }
Rgb operator+(const Rgb& a, const Rgb& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

// thick, ux, uy, uz: .cal expressions in the function file's context. Brume evaluates them once, so they
// must not depend on the hit (Radiance evaluates them per ray); the transform turns the up vector.
struct Orientation {
    double thick;
    dvec3 up;
};

Orientation orientation(const SceneObject& o) {
    PatternLibrary library;
    cal::Scope scope = library.load(o.strings[5], o.where);
    cal::ExprId exprs[4];
    for (int k = 0; k < 4; ++k) exprs[k] = library.expression(o.strings[k == 0 ? 0 : size_t(k + 1)], scope, o.where);
    library.finish();
    const cal::Program& p = library.program();
    double v[4];
    for (int k = 0; k < 4; ++k) {
        const cal::Node& root = p.nodes[p.entries[exprs[k].entry].root];
        if (root.op != cal::Op::Const)
            badArguments(o, "\"" + o.strings[k == 0 ? 0 : size_t(k + 1)] +
                                "\" varies over the surface; Brume takes only constant thickness and up vectors");
        v[k] = root.value;
    }
    PatternFrame frame = PatternFrame::fromArguments(o, std::span(o.strings).subspan(6));
    return {v[0] * frame.toWorld.scale, frame.toWorld.vector(dvec3(v[1], v[2], v[3]))};
}

KlemsBsdf load(const SceneObject& o) {
    if (o.strings.size() < 6) badArguments(o, "expected 6 or more strings");
    std::string path = findOnRayPath(o.strings[1]);
    if (path.empty()) throw Error(o.where, "cannot find BSDF file \"" + o.strings[1] + "\" for " + o.name);
    return KlemsBsdf(readKlemsXml(path, path));
}

}  // namespace

BsdfMaterial::BsdfMaterial(const SceneObject& o, const MaterialSettings& settings)
    : settings_(settings), name_(o.name), bsdf_(load(o)) {
    static std::atomic<uint64_t> materials{0};
    id_ = ++materials;
    if (!o.integers.empty()) badArguments(o, "expected 0 integers");
    readDiffuse(o);
    Orientation orient = orientation(o);
    up_ = orient.up;
    // Radiance's nonzero thickness makes the surface a proxy for detail geometry behind it (view and shadow
    // rays pass, transmitted rays start beyond it); Brume treats every BSDF surface as thin.
    if (std::abs(orient.thick) > kTiny)
        warnOnce("BSDF \"" + o.name + "\": thickness " + o.strings[0] + " taken as 0 (a thin surface); " +
                 "Brume has no proxy BSDF surfaces yet");
}

void BsdfMaterial::readDiffuse(const SceneObject& o) {
    size_t n = o.reals.size();
    if (n > 9 || n % 3 != 0) badArguments(o, "expected 0, 3, 6 or 9 reals");
    auto rgb = [&](size_t k) { return Rgb{float(o.reals[k]), float(o.reals[k + 1]), float(o.reals[k + 2])}; };
    if (n >= 3) extraReflect_[0] = rgb(0);
    if (n >= 6) extraReflect_[1] = rgb(3);
    if (n >= 9) extraTransmit_ = rgb(6);
}

std::optional<BsdfMaterial::Frame> BsdfMaterial::frameAt(const Shading& s) const {
    Frame f;
    f.z = s.backside ? -s.normal : s.normal;
    // In an instance or mesh the up vector turns with it (Radiance's object transform).
    dvec3 up = s.object ? s.object->toWorld.vector(up_) : up_;
    dvec3 x = glm::cross(up, f.z);
    double length = glm::length(x);
    if (!(length > 1e-9)) return std::nullopt;
    f.x = x / length;
    f.y = glm::cross(f.z, f.x);
    return f;
}

double BsdfMaterial::Split::share(bool transmit) const {
    double r = sampled[0] ? albedo[0] : 0, t = sampled[1] ? albedo[1] : 0;
    if (!sampled[transmit] || !(r + t > 0)) return 0;
    return (transmit ? t : r) / (r + t);
}

std::optional<BsdfMaterial::View> BsdfMaterial::viewAt(const Shading& s) const {
    auto frame = frameAt(s);
    if (!frame) return std::nullopt;
    return View{*frame, frame->toLocal(-s.dir)};
}

BsdfMaterial::Split BsdfMaterial::split(const View& v) const {
    // The integrator asks again at the same hit for every light sample (pdf) and the sampled ray: the last
    // answer is kept per thread.
    thread_local uint64_t lastMaterial = 0;
    thread_local dvec3 lastView;
    thread_local Split last;
    if (lastMaterial == id_ && lastView == v.view) return last;
    Split s;
    for (int t = 0; t < 2; ++t) {
        s.albedo[t] = bsdf_.smoothedAlbedo(v.view, t == 1);
        s.sampled[t] = s.albedo[t] > settings_.specularThreshold + kTiny;
    }
    lastMaterial = id_, lastView = v.view, last = s;
    return s;
}

bool BsdfMaterial::scatter(const Shading& s, Lobes& lobes) const {
    if (s.backside && !settings_.backVisible) return false;
    auto v = viewAt(s);
    if (!v) {  // Radiance: the surface is black here
        warnOnce("BSDF \"" + name_ + "\": up vector parallel to the surface normal");
        return true;
    }
    bool front = !s.backside;
    Split split = this->split(*v);
    lobes.diffuse = spectrum(bsdf_.diffuseReflection(front) + extraReflect_[front ? 0 : 1]) * s.pattern;
    lobes.diffuseTrans = spectrum(bsdf_.diffuseTransmission(front) + extraTransmit_) * s.pattern;
    lobes.ambient = lobes.diffuse;
    lobes.ambientTrans = lobes.diffuseTrans;
    // Non-diffuse scattering below -st joins the ambient calculation (without colour, as in Radiance;
    // patterns colour transmission only).
    if (!split.sampled[0] && split.albedo[0] > kTiny) lobes.ambient += Spectrum(float(split.albedo[0]));
    if (!split.sampled[1] && split.albedo[1] > kTiny) lobes.ambientTrans += s.pattern * float(split.albedo[1]);
    if (split.albedo[0] + split.albedo[1] > kTiny) {
        lobes.general = &lobe_;
        lobes.sampleGeneral = split.sampled[0] || split.sampled[1];
    }
    return true;
}

// f·|cos θ| with patterns colouring transmission only.
Spectrum BsdfMaterial::response(const Shading& s, const View& v, const dvec3& light) const {
    dvec3 l = v.frame.toLocal(light);
    if (std::abs(l.z) <= kTiny) return Spectrum(0.f);
    Spectrum f = spectrum(bsdf_.smoothedValue(v.view, l)) * float(std::abs(l.z));
    return (l.z > 0) != (v.view.z > 0) ? f * s.pattern : f;
}

Spectrum BsdfMaterial::Lobe::response(const Shading& s, const dvec3& wi) const {
    auto v = m_.viewAt(s);
    return v ? m_.response(s, *v, wi) : Spectrum(0.f);
}

double BsdfMaterial::Lobe::pdf(const Shading& s, const dvec3& wi) const {
    auto v = m_.viewAt(s);
    if (!v) return 0;
    dvec3 l = v->frame.toLocal(wi);
    double share = m_.split(*v).share((l.z > 0) != (v->view.z > 0));
    return share > 0 ? share * m_.bsdf_.smoothedProjectedPdf(v->view, l) * std::abs(l.z) : 0.0;
}

// One side by its share of the sampled albedo, then a patch and a direction in it.
std::optional<LobeSample> BsdfMaterial::Lobe::sample(const Shading& s, double u, double v) const {
    auto view = m_.viewAt(s);
    if (!view) return std::nullopt;
    double reflect = m_.split(*view).share(false);
    bool transmit = u >= reflect;
    double share = transmit ? 1 - reflect : reflect;
    if (!(share > 0)) return std::nullopt;
    u = transmit ? (u - reflect) / share : u / share;
    auto l = m_.bsdf_.smoothedSample(view->view, transmit, std::min(u, 1 - 1e-12), v);
    if (!l) return std::nullopt;
    double pdf = share * m_.bsdf_.smoothedProjectedPdf(view->view, *l) * std::abs(l->z);
    if (!(pdf > 0)) return std::nullopt;
    return LobeSample{view->frame.toWorld(*l), m_.response(s, *view, view->frame.toWorld(*l)) * float(1 / pdf),
                      pdf, transmit};
}

}  // namespace brume
