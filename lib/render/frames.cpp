#include "render/frames.h"

#include <istream>
#include <memory>
#include <sstream>
#include <string>

#include "util/options.h"
#include "view/view.h"

namespace brume {

Frames Frames::single(const View& view, std::optional<double> time) {
    auto done = std::make_shared<bool>(false);
    return Frames([=]() -> std::optional<SequenceFrame> {
        if (*done) return std::nullopt;
        *done = true;
        return SequenceFrame{view, 0, time};
    });
}

Frames Frames::viewLines(std::istream& in, const View& start, int first, std::optional<double> time) {
    auto last = std::make_shared<SequenceFrame>(SequenceFrame{start, first - 1, time});
    return Frames([&in, last]() -> std::optional<SequenceFrame> {
        std::string line;
        while (std::getline(in, line)) {
            if (!isViewLine(line)) continue;
            bool moved = parseViewString(last->view, line) > 0;
            std::istringstream words(line);
            for (std::string w; words >> w;)
                if (w == "-T" && words >> w) last->time = toReal("-T", w), moved = true;
            if (!moved) continue;  // a line that moves nothing is no frame, as in Radiance
            ++last->number;
            return *last;
        }
        return std::nullopt;
    });
}

Frames Frames::along(const CameraPath& path, const View& base, double fps, int first) {
    auto frames = std::make_shared<std::vector<TimedView>>(path.frames(base, fps));
    auto at = std::make_shared<size_t>(0);
    return Frames([=]() -> std::optional<SequenceFrame> {
        if (*at == frames->size()) return std::nullopt;
        const TimedView& tv = (*frames)[(*at)++];
        return SequenceFrame{tv.view, first + int(*at) - 1, tv.time};
    });
}

}  // namespace brume
