// Which instants a run keeps state for (the smoke built at an instant, the irradiance cache's records): each
// instant its own where the scene's smoke changes in time, one for all where nothing does. The one policy the
// media and the record stores share.
#pragma once

namespace brume {

class InstantKeys {
public:
    explicit InstantKeys(bool timed) : timed_(timed) {}

    bool timed() const { return timed_; }
    // The key the state of instant `time` is kept under: the instant itself, or 0 for every instant.
    double of(double time) const { return timed_ ? time : 0.0; }
    // Whether state kept under `key` is still wanted once a run has moved on to instant `time`.
    bool keptAt(double key, double time) const { return key == of(time); }

private:
    bool timed_;
};

}  // namespace brume
