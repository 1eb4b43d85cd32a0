// The CIE's data tables as the CIE publishes them (lib/spectrum/cie/*.csv, see the README there), compiled
// into the library by CMake (cmake/embed.cmake); read through cie_tables.h.
#pragma once
#include "util/embedded_file.h"

namespace brume {

// Every embedded table, sorted by name (defined in the generated cie_library.cpp).
std::span<const EmbeddedFile> embeddedCieTables();

}  // namespace brume
