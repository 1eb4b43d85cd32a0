#include "view/view_file.h"

#include <gtest/gtest.h>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "scratch_dir.h"
#include "util/error.h"

using namespace brume;

namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    return brume_test::scratchDir("view_file") / name;
}

std::string write(const std::string& name, const std::string& text) {
    fs::path p = scratch(name);
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
}

View parse(const std::string& text) {
    View v;
    parseViewString(v, text);
    return v;
}

}  // namespace

// Later lines override the options they name; the others keep earlier values; lines that are not views
// (as isViewLine decides) are skipped even when they hold view options.
TEST(ViewFile, LinesApplyCumulativelyInOrder) {
    std::string path = write("a.vf",
                             "rvu -vtv -vp 1 1 1 -vd 0 1 0 -vh 60 -vv 40\n"
                             "note -vp 9 9 9\n"
                             "VIEW= -vp 2 0 1 -vu 0 0 1\n"
                             "rpict -vd 1 1 0 -vv 45 -vs .1\n");
    View v = parse("-vtl -va 5");
    ASSERT_TRUE(readViewFile(path, v));
    EXPECT_EQ(v, parse("-vtv -vp 2 0 1 -vd 1 1 0 -vu 0 0 1 -vh 60 -vv 45 -va 5 -vs .1"));
}

TEST(ViewFile, NoViewLeavesTheViewAlone) {
    View v = parse("-vh 30");
    EXPECT_FALSE(readViewFile(write("none.vf", "just text\n-vp 1 2 3\n"), v));
    EXPECT_FALSE(readViewFile(write("empty.vf", ""), v));
    EXPECT_FALSE(readViewFile(write("binary.vf", std::string("\x01\x02 rvu -vp 1 2 3\n")), v));
    EXPECT_EQ(v, parse("-vh 30"));
}

TEST(ViewFile, MissingFileIsAnError) {
    View v;
    try {
        readViewFile("/nonexistent/x.vf", v);
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/x.vf: cannot open");
    }
}

// A picture's header: its VIEW= and command lines, up to the blank line; the resolution line follows.
TEST(ViewFile, PictureHeaderGivesViewAndResolution) {
    std::string path = write("p.hdr",
                             "#?RADIANCE\nrpict -vtv -vp 0 0 1 -vh 50 -vv 40\nVIEW= -vu 0 .2 1\n"
                             "FORMAT=32-bit_rle_rgbe\n\n-X 4 +Y 3\nVIEW= -vh 10 (pixel data, not header)\n");
    View v;
    Resolution r;
    ASSERT_TRUE(readViewFile(path, v, &r));
    EXPECT_EQ(v, parse("-vtv -vp 0 0 1 -vh 50 -vv 40 -vu 0 .2 1"));
    EXPECT_EQ(r.width, 4);
    EXPECT_EQ(r.height, 3);
    EXPECT_TRUE(r.transposed);
    EXPECT_TRUE(r.flipX);
    EXPECT_TRUE(r.flipY);
    // a view file is no picture
    View w;
    EXPECT_THROW(readViewFile(write("v.vf", "rvu -vh 20\n"), w, &r), Error);
}

// Brume's OpenEXR pictures carry their view in a string attribute "view".
TEST(ViewFile, OpenExrViewAttribute) {
    std::string path = scratch("v.exr").string();
    {
        Imf::Header header(3, 2);
        header.insert("view", Imf::StringAttribute("-vta -vp 1 2 3 -vh 180 -vv 90"));
        Imf::RgbaOutputFile file(path.c_str(), header, Imf::WRITE_RGBA);
        std::vector<Imf::Rgba> pixels(6, Imf::Rgba(0, 0, 0, 1));
        file.setFrameBuffer(pixels.data(), 1, 3);
        file.writePixels(2);
    }
    View v;
    Resolution r;
    ASSERT_TRUE(readViewFile(path, v, &r));
    EXPECT_EQ(v, parse("-vta -vp 1 2 3 -vh 180 -vv 90"));
    EXPECT_EQ(r.width, 3);
    EXPECT_EQ(r.height, 2);
    EXPECT_EQ(r.line(), "-Y 2 +X 3");
}
