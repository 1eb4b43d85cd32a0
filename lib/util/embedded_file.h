// A file shipped inside Brume's library (cmake/embed.cmake): standard .cal files, fonts. Found when a
// name is not on RAYPATH, so Brume works without Radiance's library installed.
#pragma once
#include <algorithm>
#include <span>
#include <string_view>

namespace brume {

struct EmbeddedFile {
    std::string_view name;  // e.g. "source.cal"
    std::string_view text;
};

// The file called `name` among `files`, or nullptr.
inline const EmbeddedFile* findEmbedded(std::span<const EmbeddedFile> files, std::string_view name) {
    auto it = std::find_if(files.begin(), files.end(), [&](const EmbeddedFile& f) { return f.name == name; });
    return it == files.end() ? nullptr : &*it;
}

}  // namespace brume
