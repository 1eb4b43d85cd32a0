// The frames a run renders, in order: one view; the view lines of a sequence (rpict -S), each changing the
// view as Radiance's rpict does and perhaps the scene's instant (-T); or a camera path's frames (-path,
// -fps), each at its own instant.
#pragma once
#include <functional>
#include <iosfwd>
#include <optional>

#include "render/camera_path.h"
#include "view/view.h"

namespace brume {

struct SequenceFrame {
    View view;
    int number;                  // 0: a single picture
    std::optional<double> time;  // the scene's instant (s); none where no -T was given
};

class Frames {
public:
    static Frames single(const View& view, std::optional<double> time);
    // View lines read from `in` (lines that are not views, or move nothing, are skipped), numbered from
    // `first`; each changes the view before it, starting from `start`, and a -T on it changes the instant for
    // it and those after: a line moving only the instant is a frame.
    static Frames viewLines(std::istream& in, const View& start, int first, std::optional<double> time);
    // The frames of `path` at `fps` (0: one per key), its views completing `base`, numbered from `first`.
    static Frames along(const CameraPath& path, const View& base, double fps, int first);

    // The next frame, or none after the last.
    std::optional<SequenceFrame> next() { return next_(); }

private:
    explicit Frames(std::function<std::optional<SequenceFrame>()> next) : next_(std::move(next)) {}
    std::function<std::optional<SequenceFrame>()> next_;
};

}  // namespace brume
