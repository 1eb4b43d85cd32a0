#include "render/frame_output.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "util/error.h"

using namespace brume;

TEST(FrameOutput, FileNamesCarryTheFrameNumber) {
    EXPECT_EQ(frameFileName("frame%03d.hdr", 7), "frame007.hdr");
    EXPECT_EQ(frameFileName("f%d_100%%.exr", 12), "f12_100%.exr");
    EXPECT_EQ(frameFileName("still.hdr", 3), "still.hdr");
    EXPECT_TRUE(namesFrames("a%-4i"));
    EXPECT_FALSE(namesFrames("a%%d"));
    EXPECT_THROW(frameFileName("a%s.hdr", 1), Error);  // never a string from an int: no format attacks
    EXPECT_THROW(frameFileName("a%d%d.hdr", 1), Error);
}

// A claimed frame is not claimed again (another process renders it); a picture file appears whole, replacing
// the claim.
TEST(FrameOutput, ClaimsAreExclusiveAndWritesReplaceThem) {
    auto dir = std::filesystem::temp_directory_path() / ("brume_frames_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::string path = (dir / "f1.hdr").string();
    std::filesystem::remove(path);
    EXPECT_TRUE(claimFile(path));
    EXPECT_FALSE(claimFile(path));
    Picture p;
    p.width = 3, p.height = 2;
    p.pixels.assign(18, 0.5f);
    writePictureFile(path, p, false);
    Picture back = readPicture(path);
    ASSERT_EQ(back.pixels.size(), p.pixels.size());
    EXPECT_NEAR(back.pixels[17], 0.5, 0.5 / 128);  // RGBE: 8-bit mantissas
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);  // no temporary left
    EXPECT_THROW(claimFile((dir / "no/such/dir/f.hdr").string()), Error);
    EXPECT_THROW(writePictureFile((dir / "no/such/dir/f.hdr").string(), p, false), Error);
    EXPECT_THROW(writeDepthFile((dir / "f1.hdr/d.z").string(), {1.f}), Error);  // a file is no directory
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
    std::filesystem::remove_all(dir);
}
