// Brume's standard .cal files (lib/cal/library/*.cal), compiled into the library by CMake
// (cmake/embed.cmake): found when a name is not on RAYPATH. Adding a file to that folder is all it
// takes to ship it.
#pragma once
#include "util/embedded_file.h"

namespace brume::cal {

// Every embedded file, sorted by name (defined in the generated cal_library.cpp).
std::span<const EmbeddedFile> embeddedCalFiles();

}  // namespace brume::cal
