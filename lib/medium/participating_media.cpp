#include "medium/participating_media.h"

#include <algorithm>
#include <cmath>

#include "medium/forced_collision.h"

namespace brume {

namespace {

// Whether the ray meets the box between start and end.
bool crosses(const Bounds3& b, const Ray& ray, double start, double end) {
    return clipToBox(b, ray.org, ray.dir, start, end);
}

// `sum` (in order, covering what it covers) with the piecewise-constant `add` added over its stretches.
void addSegments(std::vector<MajorantSegment>& sum, const std::vector<MajorantSegment>& add,
                 std::vector<MajorantSegment>& scratch) {
    scratch.clear();
    size_t j = 0;
    for (const MajorantSegment& s : sum) {
        double t = s.t0;
        while (t < s.t1) {
            while (j < add.size() && add[j].t1 <= t) ++j;
            if (j == add.size() || add[j].t0 >= s.t1) {
                scratch.push_back({t, s.t1, s.majorant, s.minorant});
                break;
            }
            if (add[j].t0 > t) {
                scratch.push_back({t, add[j].t0, s.majorant, s.minorant});
                t = add[j].t0;
            }
            double end = std::min(s.t1, add[j].t1);
            scratch.push_back({t, end, s.majorant + add[j].majorant, s.minorant + add[j].minorant});
            t = end;
        }
    }
    sum.swap(scratch);
}

// The largest band, or the smallest positive one (0 if none is).
double bandOf(const Spectrum& s, ParticipatingMedia::Band band) {
    if (band == ParticipatingMedia::Band::Largest) return std::max(0.f, s.maxValue());
    double least = 0;
    for (int i = 0; i < s.size(); ++i)
        if (s[i] > 0 && (least == 0 || s[i] < least)) least = s[i];
    return least;
}

}  // namespace

ParticipatingMedia::ParticipatingMedia(std::vector<SmokeVolume> smoke) : smoke_(std::move(smoke)) {
    double power = 0;
    for (size_t i = 0; i < smoke_.size(); ++i)
        if (const EmissionCells& cells = smoke_[i].flames(); !cells.empty()) {
            flames_.push_back({i, cells.power()});
            power += cells.power();
            flameBox_.include(cells.box());
        }
    for (Flame& f : flames_) f.share /= power;
}

dvec3 ParticipatingMedia::sampleFlame(double u0, double u1, double u2, double u3) const {
    size_t i = 0;
    for (; i + 1 < flames_.size() && u0 >= flames_[i].share; ++i) u0 -= flames_[i].share;
    return smoke_[flames_[i].volume].flames().sample(std::min(u0 / flames_[i].share, 0x1.fffffffffffffp-1), u1, u2, u3);
}

double ParticipatingMedia::flameDirectionDensity(const dvec3& from, const dvec3& dir) const {
    double sum = 0;
    for (const Flame& f : flames_) sum += f.share * smoke_[f.volume].flames().directionDensity(from, dir);
    return sum;
}

Spectrum ParticipatingMedia::emittedAlong(const Ray& ray, double start, double end, const HomogeneousMedium& h,
                                          Random& random, Spectrum& transmittance, int points) const {
    auto stretch = [&](double t0, double t1) { return ParticipatingMedia::transmittance(ray, t0, t1, h); };
    std::vector<MajorantSegment> segments;
    majorants(ray, start, end, &h, segments);
    ForcedCollision forced(segments);
    Spectrum sum(0.f);
    if (segments.empty() || !(forced.reach() > 0)) {
        transmittance = stretch(start, end);
        return sum;
    }
    UniformCollision even(segments);
    double uniform = std::isfinite(even.length()) ? 0.5 * looseLength(segments) / even.length() : 0;
    DistanceMixture mixture(segments.front().t0, segments.back().t1);
    mixture.add(uniform, &even);
    mixture.add(1 - uniform, &forced);
    Spectrum t(1.f);
    double at = start, u = random.uniform();
    for (int k = 0; k < points && !t.isBlack(); ++k) {
        double next = mixture.sample((k + u) / points, at);  // in order: each searched for from the last
        double density = mixture.density(next);
        t *= stretch(at, next);
        at = next;
        if (density > 0) sum.addProduct(t, emission(ray.at(next)), float(1 / (density * points)));
    }
    transmittance = t.isBlack() ? t : t * stretch(at, end);
    return sum;
}

Spectrum ParticipatingMedia::transmittance(const Ray& ray, double start, double end, const HomogeneousMedium& h) const {
    Spectrum t = h.transmittance(end - start);
    return t.isBlack() || !hasSmoke() ? t : t * smokeTransmittance(ray, start, end);
}

bool ParticipatingMedia::smokeAlong(const Ray& ray, double start, double end) const {
    return std::any_of(smoke_.begin(), smoke_.end(),
                       [&](const SmokeVolume& v) { return crosses(v.bounds(), ray, start, end); });
}

bool ParticipatingMedia::scatters(const HomogeneousMedium& h) const {
    return h.scatters() ||
           std::any_of(smoke_.begin(), smoke_.end(), [](const SmokeVolume& v) { return !v.albedo().isBlack(); });
}

double ParticipatingMedia::asymmetry(const Ray& ray, double start, double end, const HomogeneousMedium& h) const {
    double sum = 0, weights = 0;
    for (const SmokeVolume& v : smoke_) {
        double w = brightness(v.albedo());
        if (w > 0 && crosses(v.bounds(), ray, start, end)) sum += w * v.g(), weights += w;
    }
    return weights > 0 ? sum / weights : h.g;
}

void ParticipatingMedia::majorants(const Ray& ray, double start, double end, const HomogeneousMedium* h,
                                   std::vector<MajorantSegment>& out, Band band) const {
    thread_local std::vector<MajorantSegment> smoke, scratch;
    out.clear();
    const double homogeneous = h ? bandOf(h->extinction, band) : 0.0;
    out.push_back({start, end, homogeneous, homogeneous});
    for (const SmokeVolume& v : smoke_) {
        if (!crosses(v.bounds(), ray, start, end)) continue;
        const Spectrum& k = v.extinctionPerDensity();
        if (!(k.maxValue() > 0)) continue;
        double scale = band == Band::Largest ? 1.0 : bandOf(k, band) / bandOf(k, Band::Largest);
        smoke.clear();
        v.forEachBound(ray, start, end, [&](double t0, double t1, double most, double least) {
            smoke.push_back({t0, t1, most * scale, least * scale});
            return true;
        });
        addSegments(out, smoke, scratch);
    }
    std::erase_if(out, [](const MajorantSegment& s) { return !(s.majorant > 0) || !(s.t1 > s.t0); });
}

Spectrum ParticipatingMedia::smokeTransmittance(const Ray& ray, double start, double end) const {
    Spectrum t(1.f);
    for (const SmokeVolume& v : smoke_)
        if (!t.isBlack() && crosses(v.bounds(), ray, start, end)) t *= v.transmittance(ray, start, end);
    return t;
}

bool ParticipatingMedia::emits() const {
    return std::any_of(smoke_.begin(), smoke_.end(), [](const SmokeVolume& v) { return v.emits(); });
}

Spectrum ParticipatingMedia::emission(const dvec3& p) const {
    Spectrum sum(0.f);
    for (const SmokeVolume& v : smoke_)
        if (v.emits()) sum += v.emission(p);
    return sum;
}

Spectrum ParticipatingMedia::smokeExtinction(const dvec3& p) const {
    Spectrum sum(0.f);
    for (const SmokeVolume& v : smoke_) sum += v.extinction(p);
    return sum;
}

void ParticipatingMedia::scattering(const dvec3& p, const HomogeneousMedium& h, const Spectrum& scale,
                                    PhaseMixture& out) const {
    out.add(h.extinction * h.albedo * scale, h.g);
    for (const SmokeVolume& v : smoke_) out.add(v.extinction(p) * v.albedo() * scale, v.g());
}

}  // namespace brume
