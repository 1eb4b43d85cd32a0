// Brume's own font files (lib/pattern/fonts/*.fnt, made by make_font.py there), compiled into the library
// by CMake (cmake/embed.cmake): found when a font's name is not on RAYPATH.
#pragma once
#include "util/embedded_file.h"

namespace brume {

// Every embedded font, sorted by name (defined in the generated font_library.cpp).
std::span<const EmbeddedFile> embeddedFontFiles();

}  // namespace brume
