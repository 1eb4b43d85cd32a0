// What a scene's computed values depend on, as one fingerprint: caches of those values (irradiance cache
// files, -af) keep it to refuse being reused with another scene.
#pragma once
#include <string>

#include "scene/scene.h"

namespace brume {

// A hash (32 hex digits) of every object of the scene (type, modifier, identifier, string, integer and real
// arguments) and of the bytes of every file its string arguments name along RAYPATH (octrees and meshes,
// .cal, data, picture, text, font and BSDF files). Where the scene was read from (file names, lines,
// whitespace, comments) does not count. Throws Error when a named file cannot be read.
std::string sceneContentHash(const Scene& scene);

}  // namespace brume
