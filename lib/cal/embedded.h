// Brume's standard .cal files (lib/cal/library/*.cal), compiled into the library by CMake
// (lib/cal/embed.cmake): found when a name is not on RAYPATH. Adding a file to that folder is all it
// takes to ship it.
#pragma once
#include <span>
#include <string_view>

namespace brume::cal {

struct EmbeddedFile {
    std::string_view name;  // e.g. "source.cal"
    std::string_view text;
};

// Every embedded file, sorted by name (defined in the generated cal_library.cpp).
std::span<const EmbeddedFile> embeddedCalFiles();

}  // namespace brume::cal
