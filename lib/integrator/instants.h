// The instants a run traces light at: the scene's smoke at each, built on first use by whichever thread asks
// first (the same smoke whoever builds it), and the last instant where every smoke that evolves has data.
// The one registry of instants that the media (their smoke) and the irradiance caches (the windows of time
// their records serve, RecordWindows) consult: no instant needs preparing before rays are traced at it.
#pragma once
#include <map>
#include <memory>
#include <mutex>

#include "cache/record_windows.h"
#include "medium/participating_media.h"
#include "world/render_scene.h"

namespace brume {

class Instants {
public:
    // `majorantCell`: -mc, the majorant grids' cell edge in voxels.
    Instants(const RenderScene& scene, int majorantCell);
    Instants(const Instants&) = delete;
    Instants& operator=(const Instants&) = delete;

    // Whether the scene looks different at different instants (smoke with several key frames): else one
    // smoke serves every instant.
    bool timed() const { return timed_; }
    // The last instant where every smoke that evolves has data (infinity where none evolves).
    double last() const { return last_; }
    // The windows of time irradiance cache records serve at these instants, `longest` s at most (-at).
    RecordWindows recordWindows(double longest) const { return RecordWindows(timed_, last_, longest); }

    // The smoke at instant `time`: from any thread, at any time but while forgetBefore runs. Error (naming the
    // smoke and its key frames) at an instant outside them.
    const ParticipatingMedia& smokeAt(double time);
    // Forgets the smoke of the instants before `time` (a run that has moved on). Not while rays are traced.
    void forgetBefore(double time);

private:
    const RenderScene& scene_;
    int majorantCell_;
    bool timed_;
    double last_;
    std::mutex mutex_;
    std::map<double, std::unique_ptr<const ParticipatingMedia>> smoke_;  // by instant; one, under 0, where untimed
};

}  // namespace brume
