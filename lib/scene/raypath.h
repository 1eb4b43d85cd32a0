// Finding scene, data and .cal files as Radiance does: along the colon-separated RAYPATH.
#pragma once
#include <span>
#include <string>

#include "util/embedded_file.h"
#include "util/error.h"

namespace brume {

// The file's path if `name` is found (absolute, ./ or ../ names as given; others along RAYPATH, default
// ".:/usr/local/lib/ray"), or an empty string.
std::string findOnRayPath(const std::string& name);

// A file's text and the name messages cite it by: its path, or the bare name of a file shipped in Brume.
struct FileText {
    std::string origin;
    std::string text;
};

// The file `name` along RAYPATH, or else the one so named among `shipped` (Brume's own library, so that
// Brume works without Radiance's installed). Throws Error "cannot find <kind> "name"" (at `where`) when
// neither has it, and when the file found cannot be read.
FileText readLibraryFile(const std::string& name, std::span<const EmbeddedFile> shipped, const std::string& kind,
                         const SourceLocation& where = {});

}  // namespace brume
