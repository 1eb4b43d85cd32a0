#include "scene/raypath.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

namespace brume {

namespace {

bool readable(const std::string& path) { return access(path.c_str(), R_OK) == 0; }

// Names Radiance takes as given rather than searching for them.
bool isExplicit(std::string_view name) {
    return name.starts_with('/') || name.starts_with("./") || name.starts_with("../") || name == "." ||
           name == "..";
}

}  // namespace

std::string findOnRayPath(const std::string& name) {
    if (name.empty()) return {};
    if (isExplicit(name)) return readable(name) ? name : std::string();
    const char* env = std::getenv("RAYPATH");
    std::string_view path = env ? env : ".:/usr/local/lib/ray";
    // Each colon-separated directory in turn; an empty one or "." means the current directory (where
    // the name is returned as is, for shorter messages).
    for (;;) {
        size_t colon = path.find(':');
        std::string dir(path.substr(0, colon));
        std::string candidate = dir.empty() || dir == "." ? name : dir.ends_with('/') ? dir + name : dir + "/" + name;
        if (readable(candidate)) return candidate;
        if (colon == std::string_view::npos) return {};
        path.remove_prefix(colon + 1);
    }
}

FileText readLibraryFile(const std::string& name, std::span<const EmbeddedFile> shipped, const std::string& kind,
                         const SourceLocation& where) {
    if (std::string path = findOnRayPath(name); !path.empty()) {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw Error("cannot open " + kind + " \"" + path + "\"");
        std::ostringstream text;
        text << in.rdbuf();
        return {path, text.str()};
    }
    if (const EmbeddedFile* file = findEmbedded(shipped, name)) return {name, std::string(file->text)};
    std::string what = "cannot find " + kind + " \"" + name + "\"";
    throw where.file.empty() ? Error(what) : Error(where, what);
}

}  // namespace brume
