#include "render/camera_path.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <glm/geometric.hpp>

#include "scratch_dir.h"
#include "util/error.h"

using namespace brume;

namespace {

std::string pathFile(const std::string& text) {
    auto p = brume_test::scratchDir("camera_path") / "path.txt";
    std::ofstream(p) << text;
    return p.string();
}

std::string readError(const std::string& text) {
    try {
        CameraPath::read(pathFile(text), {0, 0, 1});
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

// Halfway in time between two keys the camera is halfway along, looking halfway round (45° between 0° and
// 90°), its focal distance (the direction's length) halfway between 2 and 4.
TEST(CameraPath, InterpolatesPositionDirectionAndFocalDistance) {
    CameraPath p = CameraPath::read(pathFile("# t  position  direction\n"
                                             "0   0 0 1.6   2 0 0\n"
                                             "2   4 0 1.6   0 4 0   # turning left\n"),
                                    {0, 0, 1});
    View base;
    base.vh = 70;
    View v = p.at(1, base);
    EXPECT_NEAR(v.vp.x, 2, 1e-12);
    EXPECT_NEAR(glm::length(v.vd), 3, 1e-12);
    EXPECT_NEAR(v.vd.x, v.vd.y, 1e-12);
    EXPECT_EQ(v.vh, 70);
    EXPECT_EQ(p.at(-5, base).vp, dvec3(0, 0, 1.6));  // before the first key: the first key
    EXPECT_EQ(p.at(9, base).vp, dvec3(4, 0, 1.6));
}

// 25 frames a second over 2 s: 51 frames, the last on the last key; no rate: one frame per key.
TEST(CameraPath, FramesAtARate) {
    CameraPath p = CameraPath::read(pathFile("0 0 0 0 0 1 0\n0.5 1 0 0 0 1 0\n2 2 0 0 0 1 0 0 0 1\n"), {0, 0, 1});
    auto frames = p.frames(View{}, 25);
    ASSERT_EQ(frames.size(), 51u);
    EXPECT_DOUBLE_EQ(frames.back().time, 2);
    EXPECT_NEAR(frames[25].view.vp.x, 1 + 0.5 / 1.5, 1e-12);
    EXPECT_EQ(p.frames(View{}, 0).size(), 3u);
}

TEST(CameraPath, BadFilesAreRefusedWithTheirLine) {
    EXPECT_NE(readError("0 0 0 0 1 0 0\n1 0 0 0 1 0\n").find(":2: expected time"), std::string::npos);
    EXPECT_NE(readError("0 0 0 0 1 0 0\n0 1 0 0 1 0 0\n").find(":2: times must increase"), std::string::npos);
    EXPECT_NE(readError("0 0 0 0 1 0 0\n1 0 0 0 -1 0 0\n").find(":2: the camera turns half round"), std::string::npos);
    EXPECT_NE(readError("0 0 0 0 0 0 0\n").find(":1: zero view direction"), std::string::npos);
    EXPECT_NE(readError("0 0 0 nan 1 0 0\n").find("not a number"), std::string::npos);
    EXPECT_NE(readError("# nothing\n").find("no camera keys"), std::string::npos);
}
