// A visibility study at its instants: from each observer's eye, rays to points over each sign it faces and over
// the band of wall around it (its background), traced in passes (the later ones only for sight lines whose
// verdict the rays' noise could turn), their luminances measured and judged (SightMeasure, SightJudgement),
// beside the line's optical depth and the share of it the smoke has data for. The program around it only reads
// the inputs and writes what comes out (StudyReport).
#pragma once
#include <functional>
#include <vector>

#include "medium/smoke.h"
#include "render/sequence.h"
#include "world/render_scene.h"
#include "visibility/observers.h"
#include "visibility/sight.h"
#include "visibility/sign.h"

namespace brume {

// A sign with the points its rays aim at: on it, and on the band around it.
struct StudySign {
    Sign sign;
    std::vector<dvec3> on, around;
};
StudySign studySign(Sign sign, int rays);

struct StudySettings {
    VisibilityCriteria criteria{{}, 10, 0.5};
    QuotedExtinction quoted = QuotedExtinction::At633nm;  // the K of Jin's law and of the optical depth
    int rays = 32;   // to each sign and to its band, per pass
    int passes = 4;  // at most
    // Jin's law and the local criteria only: no light traced; a sign is hidden where the scene's surfaces cross
    // the straight line to its centre (verdict "not-traced" for the light).
    bool jinOnly = false;
};

struct SightLine {
    SightMeasure measure;
    SightJudgement judgement;
};

class VisibilityStudy {
public:
    VisibilityStudy(std::vector<Observer> observers, std::vector<StudySign> signs, const StudySettings& settings);

    const std::vector<Observer>& observers() const { return observers_; }
    const std::vector<StudySign>& signs() const { return signs_; }
    const StudySettings& settings() const { return settings_; }
    // Sight lines are numbered observer by observer, sign by sign within.
    size_t lines() const { return observers_.size() * signs_.size(); }
    const Observer& observerOf(size_t line) const { return observers_[line / signs_.size()]; }
    const Sign& signOf(size_t line) const { return signs_[line % signs_.size()].sign; }
    // The rays of an instant's first pass (the later passes' are as few as need them).
    size_t firstPassRays() const { return aims_.size(); }

    // Every sight line at instant `time` (a time the scene's smoke holds), each first-pass ray calling `traced`;
    // `scene` the one traced, whose surfaces hide signs from lines judged by Jin's law alone.
    std::vector<SightLine> at(double time, Sequence& sequence, const RenderScene& scene,
                              const std::function<void()>& traced) const;

private:
    std::vector<SightLine> byJinAlone(double time, Sequence& sequence, const RenderScene& scene,
                                      const std::function<void()>& traced) const;

    // One ray of an instant: from an observer's eye to a point on a sign or on the band around it.
    struct Aim {
        size_t line;
        bool onSign;
        dvec3 target;
    };

    std::vector<Observer> observers_;
    std::vector<StudySign> signs_;
    StudySettings settings_;
    std::vector<Aim> aims_;
};

}  // namespace brume
