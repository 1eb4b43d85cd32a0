// The frames of a run: one picture, the view lines of a sequence (rpict -S), a camera path's frames.
#include "render/frames.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace brume;

namespace {

std::vector<SequenceFrame> all(Frames frames) {
    std::vector<SequenceFrame> out;
    while (auto f = frames.next()) out.push_back(*f);
    return out;
}

}  // namespace

TEST(Frames, ASinglePictureIsFrameZero) {
    View v;
    v.vp = {1, 2, 3};
    std::vector<SequenceFrame> frames = all(Frames::single(v, 4.5));
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0].number, 0);
    EXPECT_EQ(frames[0].view, v);
    EXPECT_EQ(frames[0].time, 4.5);
    EXPECT_FALSE(all(Frames::single(v, std::nullopt))[0].time);
}

// Each view line changes the view before it (Radiance's rpict -S), numbered from `first`; lines that hold no
// view are skipped; a -T changes the instant from its frame on.
TEST(Frames, ViewLinesChangeTheViewCumulatively) {
    std::istringstream in("rpict -vp 1 0 0\n"
                          "# a comment\n"
                          "-vd 0 0 1 but not a view line\n"
                          "rpict -vd 1 0 0 -T 3\n"
                          "rpict\n"
                          "VIEW= -vh 60\n");
    View start;
    start.vh = 30;
    std::vector<SequenceFrame> frames = all(Frames::viewLines(in, start, 5, 1.0));
    ASSERT_EQ(frames.size(), 3u);
    EXPECT_EQ(frames[0].number, 5);
    EXPECT_EQ(frames[0].view.vp, dvec3(1, 0, 0));
    EXPECT_EQ(frames[0].view.vd, start.vd);
    EXPECT_EQ(frames[0].time, 1.0);
    EXPECT_EQ(frames[1].number, 6);
    EXPECT_EQ(frames[1].view.vp, dvec3(1, 0, 0));
    EXPECT_EQ(frames[1].view.vd, dvec3(1, 0, 0));
    EXPECT_EQ(frames[1].view.vh, 30);
    EXPECT_EQ(frames[1].time, 3.0);
    EXPECT_EQ(frames[2].number, 7);
    EXPECT_EQ(frames[2].view.vd, dvec3(1, 0, 0));
    EXPECT_EQ(frames[2].view.vh, 60);
    EXPECT_EQ(frames[2].time, 3.0);
}

// A camera path's frames, numbered from `first`, each at the path's instant for it.
TEST(Frames, AlongAPathFramesTakeThePathsTimes) {
    std::istringstream keys("0  0 0 1.6  1 0 0\n2  4 0 1.6  0 1 0\n");
    CameraPath path = CameraPath::parse(keys, "path", {0, 0, 1});
    View base;
    base.vh = 70;
    for (double fps : {0.0, 2.0}) {
        std::vector<TimedView> expected = path.frames(base, fps);
        std::vector<SequenceFrame> frames = all(Frames::along(path, base, fps, 3));
        ASSERT_EQ(frames.size(), fps > 0 ? 5u : 2u);
        ASSERT_EQ(frames.size(), expected.size());
        for (size_t i = 0; i < frames.size(); ++i) {
            EXPECT_EQ(frames[i].number, 3 + int(i));
            EXPECT_EQ(frames[i].time, expected[i].time);
            EXPECT_EQ(frames[i].view, expected[i].view);
        }
        EXPECT_EQ(frames.back().time, 2.0);
    }
}

// A line need only give what moves (rpict(1), -S): one that moves only the instant is a frame at that instant.
TEST(Frames, AViewLineMovingOnlyTheInstantIsAFrame) {
    std::istringstream in("VIEW= -vp 1 0 0 -T 0\nVIEW= -T 5\n");
    std::vector<SequenceFrame> frames = all(Frames::viewLines(in, View{}, 1, std::nullopt));
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[1].view.vp, dvec3(1, 0, 0));
    EXPECT_EQ(frames[1].time, 5.0);
}
