// Standard illuminants as Radiance data files (lib/spectrum/library/*.dat: cie_a.dat, cie_d65.dat,
// cie_f1.dat …), compiled into the library by CMake (cmake/embed.cmake): found by data-file lookups when a
// name is not on RAYPATH, so `specfile` and the data patterns can name them bare.
#pragma once
#include "util/embedded_file.h"

namespace brume {

// Every embedded spectrum file, sorted by name (defined in the generated spectra_library.cpp).
std::span<const EmbeddedFile> embeddedSpectrumFiles();

}  // namespace brume
