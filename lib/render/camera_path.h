// A walkthrough: the camera's positions and directions at key times, from a text file of lines
//   time  px py pz  dx dy dz  [ux uy uz]      (# starts a comment)
// with strictly increasing times. Views between keys are interpolated (position linearly, direction and up
// along great circles, the direction's length — the focal distance — linearly), so a frame rate gives
// evenly timed frames whatever the keys' spacing.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "view/view.h"

namespace brume {

struct CameraKey {
    double time;
    dvec3 position, direction, up;
};

struct TimedView {
    double time;
    View view;
};

class CameraPath {
public:
    // Reads the file; `defaultUp` is the up vector of keys that give none. Throws Error "file:line: ...".
    static CameraPath read(const std::string& path, const dvec3& defaultUp);
    // The same from a stream, `name` in messages.
    static CameraPath parse(std::istream& in, const std::string& name, const dvec3& defaultUp);

    // The view at `time`, clamped to the path's span; the rest of `base` (type, sizes, clipping) kept.
    View at(double time, const View& base) const;
    // The frames to render: one per key when fps is 0, else every 1/fps from the first key's time to the last.
    std::vector<TimedView> frames(const View& base, double fps) const;

    const std::vector<CameraKey>& keys() const { return keys_; }

private:
    std::vector<CameraKey> keys_;
};

}  // namespace brume
