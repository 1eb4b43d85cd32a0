#include "scene/command.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "util/error.h"

namespace brume {
namespace {

// Scenes written for Radiance call its generators ("!xform", "!gensky"); Brume's own, installed beside the
// running program, must be the ones found.
TEST(Command, CommandsFindTheRunningProgramsDirectoryFirstOnPath) {
    std::string own = std::filesystem::read_symlink("/proc/self/exe").parent_path().string();
    EXPECT_EQ(commandOutput("echo \"$PATH\"").rfind(own + ":", 0), 0u);
    EXPECT_EQ(commandOutput("command -v xform"), own + "/xform\n");
    // Nested Brume programs do not add it again.
    EXPECT_EQ(commandOutput("echo \"$PATH\"").find(own + ":" + own + ":"), std::string::npos);
}

TEST(Command, FailingCommandIsAnError) {
    EXPECT_THROW(commandOutput("exit 3"), Error);
}

}  // namespace
}  // namespace brume
