#include "visibility/study.h"

#include <cmath>
#include <numeric>

#include "spectrum/color_output.h"
#include "spectrum/colorimetry.h"

namespace brume {

namespace {

// The luminances one observer's rays to one sign brought, summed over passes.
struct Tally {
    double signSum = 0, signSquares = 0, backgroundSum = 0, backgroundSquares = 0;
    int signRays = 0, signHits = 0, backgroundRays = 0;
};

double mean(double sum, int n) { return n ? sum / n : 0; }
// The standard error of a mean of n values from their sum and sum of squares (0 for fewer than two).
double standardError(double sum, double squares, int n) {
    if (n < 2) return 0;
    double m = sum / n;
    return std::sqrt(std::max(0.0, squares / n - m * m) / (n - 1));
}

SightMeasure measure(const Observer& observer, const Sign& sign, const Tally& t, double opticalDepth, double coverage,
                     double eyeExtinction) {
    SightMeasure m;
    const dvec3 toEye = observer.eye - sign.centre;
    m.distance = glm::length(toEye);
    m.facing = facing(sign, observer.eye);
    m.signLuminance = mean(t.signSum, t.signHits);
    m.backgroundLuminance = mean(t.backgroundSum, t.backgroundRays);
    m.signError = standardError(t.signSum, t.signSquares, t.signHits);
    m.backgroundError = standardError(t.backgroundSum, t.backgroundSquares, t.backgroundRays);
    m.seenShare = t.signRays ? double(t.signHits) / t.signRays : 0;
    // A sign small beside its distance: its area times the cosine over the distance squared.
    m.solidAngle = m.facing ? sign.shape.area * glm::dot(sign.shape.normal, toEye) / std::pow(m.distance, 3) : 0;
    m.opticalDepth = opticalDepth;
    m.coverage = coverage;
    m.viewCosine = m.distance > 0 ? glm::dot(sign.shape.normal, toEye) / m.distance : 1;
    m.eyeExtinction = eyeExtinction;
    m.legibilityDistance = legibilityFactor(sign.kind) * sign.height;
    return m;
}

// Whether a sight line's verdict could go the other way by the rays' noise: its visibility level within two
// standard errors of the criterion (a sign seen, not hidden).
bool uncertain(const SightJudgement& j, const VisibilityCriteria& c) {
    bool seen = j.verdict == Verdict::Visible || j.verdict == Verdict::BelowThreshold || j.verdict == Verdict::NoData;
    return seen && std::abs(j.visibilityLevel - c.minimumLevel) < 2 * j.levelError;
}

}  // namespace

std::vector<SightLine> VisibilityStudy::byJinAlone(double time, Sequence& sequence, const RenderScene& scene,
                                                   const std::function<void()>& traced) const {
    const Integrator& integrator = sequence.integrator();
    std::vector<SightLine> out(lines());
    sequence.run(observers_.size(), time, [&](size_t o, WorkItem&) {  // prepares the instant; one item an eye
        const dvec3& eye = observers_[o].eye;
        const double atEye = integrator.quotedExtinctionAt(eye, time, settings_.quoted);
        for (size_t s = 0; s < signs_.size(); ++s) {
            const size_t line = o * signs_.size() + s;
            const Sign& sign = signs_[s].sign;
            Tally clear;
            if (facing(sign, eye)) {
                // Met before the sign's centre: hidden (a sign's own polygon, or anything beyond it, is not).
                const double d = glm::length(sign.centre - eye);
                std::optional<SurfaceHit> hit = scene.geometry().intersect(Ray(eye, (sign.centre - eye) / d));
                clear.signRays = 1;
                clear.signHits = !hit || hit->t >= d * (1 - 1e-9) || scene.surfaceObject(hit->surface) == sign.object;
                traced();
            }
            SightLine& l = out[line];
            l.measure = measure(observers_[o], sign, clear,
                                integrator.quotedDepthBetween(eye, sign.centre, time, settings_.quoted),
                                integrator.dataCoverageBetween(eye, sign.centre, time), atEye);
            l.judgement = judge(l.measure, sign.jinConstant, settings_.criteria);
            if (l.judgement.verdict != Verdict::Behind && l.judgement.verdict != Verdict::Hidden)
                l.judgement.verdict = Verdict::NotTraced;
        }
    });
    return out;
}

StudySign studySign(Sign sign, int rays) {
    StudySign s{std::move(sign), {}, {}};
    s.on = pointsOnSign(s.sign, rays);
    s.around = pointsAroundSign(s.sign, rays);
    return s;
}

VisibilityStudy::VisibilityStudy(std::vector<Observer> observers, std::vector<StudySign> signs,
                                 const StudySettings& settings)
    : observers_(std::move(observers)), signs_(std::move(signs)), settings_(settings) {
    for (size_t o = 0; o < observers_.size(); ++o)
        for (size_t s = 0; s < signs_.size(); ++s) {
            if (!facing(signs_[s].sign, observers_[o].eye)) continue;
            const size_t line = o * signs_.size() + s;
            for (const dvec3& p : signs_[s].on) aims_.push_back({line, true, p});
            for (const dvec3& p : signs_[s].around) aims_.push_back({line, false, p});
        }
}

std::vector<SightLine> VisibilityStudy::at(double time, Sequence& sequence, const RenderScene& scene,
                                           const std::function<void()>& traced) const {
    const Integrator& integrator = sequence.integrator();
    if (settings_.jinOnly) return byJinAlone(time, sequence, scene, traced);
    std::vector<Tally> tallies(lines());
    std::vector<SightLine> out(lines());
    std::vector<double> depths(lines()), coverage(lines()), atEye(observers_.size());  // once the first pass has
                                                                                        // prepared the instant
    std::vector<bool> inPass(lines(), true);  // the sight lines the pass traces rays for
    std::vector<size_t> rays(aims_.size());
    std::iota(rays.begin(), rays.end(), size_t(0));
    for (int pass = 0; pass == 0 || !rays.empty(); ++pass) {  // one pass at least: lines with no ray are judged too
        std::vector<RayRecord> records(rays.size());
        sequence.run(rays.size(), time, [&](size_t i, WorkItem& item) {
            const Aim& a = aims_[rays[i]];
            const dvec3 eye = observerOf(a.line).eye;
            records[i] = integrator.trace({eye, glm::normalize(a.target - eye), pass * aims_.size() + rays[i], time}, item);
            if (pass == 0) traced();
        });
        for (size_t o = 0; pass == 0 && o < observers_.size(); ++o)
            atEye[o] = integrator.quotedExtinctionAt(observers_[o].eye, time, settings_.quoted);
        for (size_t line = 0; pass == 0 && line < lines(); ++line) {
            const dvec3& eye = observerOf(line).eye;
            depths[line] = integrator.quotedDepthBetween(eye, signOf(line).centre, time, settings_.quoted);
            coverage[line] = integrator.dataCoverageBetween(eye, signOf(line).centre, time);
        }
        for (size_t i = 0; i < rays.size(); ++i) {
            const Aim& a = aims_[rays[i]];
            Tally& t = tallies[a.line];
            const double luminance = kWhiteEfficacy * photopic(records[i].value);
            const bool metSign = records[i].surfaceObject == signOf(a.line).object;
            if (a.onSign) {
                ++t.signRays;
                if (metSign) ++t.signHits, t.signSum += luminance, t.signSquares += luminance * luminance;
            } else if (!metSign) {  // the band's rays that graze the sign's edge do not count
                ++t.backgroundRays, t.backgroundSum += luminance, t.backgroundSquares += luminance * luminance;
            }
        }
        for (size_t line = 0; line < lines(); ++line) {
            if (!inPass[line]) continue;
            const Sign& sign = signOf(line);
            out[line].measure = measure(observerOf(line), sign, tallies[line], depths[line], coverage[line],
                                        atEye[line / signs_.size()]);
            out[line].judgement = judge(out[line].measure, sign.jinConstant, settings_.criteria);
            inPass[line] = pass + 1 < settings_.passes && uncertain(out[line].judgement, settings_.criteria);
        }
        std::erase_if(rays, [&](size_t i) { return !inPass[aims_[i].line]; });
    }
    return out;
}

}  // namespace brume
