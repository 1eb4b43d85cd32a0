#include "medium/participating_media.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/vector_relational.hpp>

#include "medium/forced_collision.h"
#include "sampling/piecewise_constant.h"
#include "spectrum/colorimetry.h"

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

// Σ weighed(t_k)/(guide's density × points) over `points` distances drawn (draw(u, from): the distance where a
// mixture's cumulative distribution reaches u, searched for from `from`) through a guide: what a draw at the
// middle of each of 2·points bins of the distribution weighs (weighed(t), the integrand over the mixture's
// density), which half of the draws then follow (PiecewiseConstant), stratified over the guide's
// distribution. Where the integrand is even in the mixture's terms (even smoke of one temperature) the guide is
// uniform and every draw weighs the same.
template <class Draw, class Weighed>
Spectrum guidedSum(const Draw& draw, int points, Random& random, const Weighed& weighed) {
    std::vector<double> guess(size_t(2 * points));
    double t = -std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < guess.size(); ++j) {
        t = draw((double(j) + 0.5) / double(guess.size()), t);  // in order: each searched for from the last
        guess[j] = brightness(weighed(t));
    }
    PiecewiseConstant guide(guess, 0.5);
    Spectrum sum(0.f);
    const double u = random.uniform();
    t = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < points; ++k) {
        double x = guide.sample((k + u) / points);
        t = draw(x, t);
        sum += weighed(t) * float(1 / (guide.density(x) * points));
    }
    return sum;
}

// Where the first collision with some of the smoke along [start, end] falls (those `counts` says), τ exact
// (DepthCollision): in its densest band, half in its clearest where they differ (soot's spectrum: the clear bands
// see deeper, and what comes from there would be left to rare draws of huge weight). The profiles of every smoke
// the stretch crosses are kept for the caller. Holds pointers into itself: neither copied nor moved.
class FirstCollision {
public:
    template <class Counts>
    FirstCollision(const std::vector<SmokeVolume>& smoke, const Ray& ray, double start, double end, Counts counts)
        : along_(profiles(smoke, ray, start, end)),
          near_(terms(smoke, counts, ParticipatingMedia::Band::Largest)),
          far_(terms(smoke, counts, ParticipatingMedia::Band::Smallest)),
          mixed_(far_.reach() > 0 && far_.reach() != near_.reach()),
          mixture_(extent(smoke, counts, true), extent(smoke, counts, false)) {
        mixture_.add(mixed_ ? 0.5 : 1.0, &near_);
        if (mixed_) mixture_.add(0.5, &far_);
    }
    FirstCollision(const FirstCollision&) = delete;
    FirstCollision& operator=(const FirstCollision&) = delete;

    // Each smoke's density along the stretch (empty where it does not cross it).
    const std::vector<DensityProfile>& profiles() const { return along_; }
    // Whether a collision can fall on the stretch at all.
    bool any() const { return near_.reach() > 0; }
    // The distance where the distribution reaches u (searched for from `from`); one smoke of one extinction
    // (grey, or RGB's even smoke) inverts its profile directly.
    double sample(double u, double from = -std::numeric_limits<double>::infinity()) const {
        return mixed_ || !near_.invertible() ? mixture_.sample(u, from) : near_.sample(u);
    }
    double density(double t) const { return mixture_.density(t); }

private:
    static std::vector<DensityProfile> profiles(const std::vector<SmokeVolume>& smoke, const Ray& ray, double start,
                                                double end) {
        std::vector<DensityProfile> along(smoke.size());
        for (size_t v = 0; v < smoke.size(); ++v)
            if (crosses(smoke[v].bounds(), ray, start, end)) along[v] = smoke[v].profile(ray, start, end);
        return along;
    }
    template <class Counts>
    std::vector<DepthCollision::Term> terms(const std::vector<SmokeVolume>& smoke, Counts counts,
                                            ParticipatingMedia::Band band) const {
        std::vector<DepthCollision::Term> out;
        for (size_t v = 0; v < smoke.size(); ++v)
            if (counts(smoke[v]) && !along_[v].empty()) out.push_back({&along_[v], bandOf(smoke[v].extinctionPerDensity(), band)});
        return out;
    }
    // Where the counted profiles start (`first`) or end.
    template <class Counts>
    double extent(const std::vector<SmokeVolume>& smoke, Counts counts, bool first) const {
        double x = first ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
        for (size_t v = 0; v < smoke.size(); ++v)
            if (counts(smoke[v]) && !along_[v].empty())
                x = first ? std::min(x, along_[v].pieces().front().a) : std::max(x, along_[v].pieces().back().b);
        return x;
    }

    std::vector<DensityProfile> along_;
    DepthCollision near_, far_;
    bool mixed_;
    DistanceMixture mixture_;
};

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
    flamePower_ = power;
}

// Half inside the flames' box, none outside it (where points drawn are at least as far as the box's faces).
double ParticipatingMedia::flameSphereShare(const dvec3& from) const {
    return flameBox_.contains(from) ? 0.5 : 0.0;
}

std::optional<dvec3> ParticipatingMedia::sampleFlameDirection(const dvec3& from, double u0, double u1, double u2,
                                                              double u3) const {
    const double sphere = flameSphereShare(from);
    if (u0 < sphere) {  // uniform over the sphere
        u0 /= sphere;
        double z = 1 - 2 * u0, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * std::numbers::pi * u1;
        return dvec3(r * std::cos(phi), r * std::sin(phi), z);
    }
    u0 = std::min((u0 - sphere) / (1 - sphere), 0x1.fffffffffffffp-1);
    size_t i = 0;
    for (; i + 1 < flames_.size() && u0 >= flames_[i].share; ++i) u0 -= flames_[i].share;
    const EmissionCells& cells = smoke_[flames_[i].volume].flames();
    dvec3 toward = cells.sample(std::min(u0 / flames_[i].share, 0x1.fffffffffffffp-1), u1, u2, u3) - from;
    double length = glm::length(toward);
    if (!(length > 0)) return std::nullopt;
    return toward / length;
}

double ParticipatingMedia::flameDirectionDensity(const dvec3& from, const dvec3& dir) const {
    if (flames_.empty()) return 0;
    double cells = 0;
    for (const Flame& f : flames_) cells += f.share * smoke_[f.volume].flames().directionDensity(from, dir);
    const double sphere = flameSphereShare(from);
    return (1 - sphere) * cells + sphere / (4 * std::numbers::pi);
}

std::optional<std::pair<double, double>> ParticipatingMedia::smokeCollision(const Ray& ray, double start, double end,
                                                                         double u) const {
    FirstCollision collision(smoke_, ray, start, end, [](const SmokeVolume&) { return true; });
    if (!collision.any()) return std::nullopt;
    const double t = collision.sample(u), density = collision.density(t);
    if (!(density > 0)) return std::nullopt;
    return std::pair{t, density};
}

Spectrum ParticipatingMedia::emittedAlong(const Ray& ray, double start, double end, const HomogeneousMedium& h,
                                          Random& random, Spectrum& transmittance, int points) const {
    // Draws where the flames' first collision falls; the transmittance through every smoke.
    FirstCollision collision(smoke_, ray, start, end, [](const SmokeVolume& v) { return v.emits(); });
    const std::vector<DensityProfile>& along = collision.profiles();
    // T from `start` to t, per band, times what the flames emit at t (the densities from the profiles).
    auto light = [&](double t) {
        Spectrum through = h.transmittance(t - start), glow(0.f);
        for (size_t v = 0; v < smoke_.size(); ++v) {
            if (along[v].empty()) continue;
            DensityProfile::Point q = along[v].at(t);
            through *= smoke_[v].transmittance(q.integral);
            if (smoke_[v].emits()) glow += smoke_[v].emission(ray.at(t), q.density);
        }
        return through * glow;
    };
    transmittance = h.transmittance(end - start);
    for (size_t v = 0; v < smoke_.size(); ++v)
        if (!along[v].empty()) transmittance *= smoke_[v].transmittance(along[v].total());
    if (!collision.any()) return Spectrum(0.f);
    return guidedSum([&](double u, double from) { return collision.sample(u, from); }, points, random, [&](double t) {
        double density = collision.density(t);
        return density > 0 ? light(t) * float(1 / density) : Spectrum(0.f);
    });
}

Spectrum ParticipatingMedia::transmittance(const Ray& ray, double start, double end, const HomogeneousMedium& h) const {
    Spectrum t = h.transmittance(end - start);
    return t.isBlack() || !hasSmoke() ? t : t * smokeTransmittance(ray, start, end);
}

double ParticipatingMedia::quotedDepth(const Ray& ray, double start, double end, const HomogeneousMedium& h,
                                       QuotedExtinction quoted) const {
    double k = photopic(h.extinction), depth = k > 0 ? k * (end - start) : 0;
    for (const SmokeVolume& v : smoke_)
        if (crosses(v.bounds(), ray, start, end))
            depth += v.quotedExtinctionPerDensity(quoted) * v.densityIntegral(ray, start, end);
    return depth;
}

double ParticipatingMedia::quotedExtinction(const dvec3& p, const HomogeneousMedium& h, QuotedExtinction quoted) const {
    double k = photopic(h.extinction);
    for (const SmokeVolume& v : smoke_) k += v.quotedExtinctionPerDensity(quoted) * v.density(p);
    return k;
}

double ParticipatingMedia::uncoveredLength(const Ray& ray, double start, double end) const {
    double most = 0;
    for (const SmokeVolume& v : smoke_) most = std::max(most, v.uncoveredLength(ray, start, end));
    return most;
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
