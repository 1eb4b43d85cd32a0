// Finding scene, data and .cal files as Radiance does: along the colon-separated RAYPATH.
#pragma once
#include <string>

namespace brume {

// The file's path if `name` is found (absolute, ./ or ../ names as given; others along RAYPATH, default
// ".:/usr/local/lib/ray"), or an empty string.
std::string findOnRayPath(const std::string& name);

}  // namespace brume
