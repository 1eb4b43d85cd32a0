// The octrees and meshes that instance and mesh objects place in a scene, loaded once per file however many
// objects name them.
#pragma once
#include "scene/scene.h"

namespace brume {

// Loads the files the scene's instance and mesh objects name (found along RAYPATH), those of the instances
// they hold too, fills Scene::placedFiles and Scene::placedFileOf, and adds the files to Scene::sources.
// The objects of an octree, and the materials of a compiled mesh, are appended to Scene::objects after the
// scene's own. A Wavefront mesh of a
// mesh object without modifier takes its usemtl names from the modifiers defined before that object.
// loadScene calls it; call it after readSceneText or readSceneFile. Throws Error (file:line) for missing,
// unreadable or malformed files.
void loadPlacedFiles(Scene& scene);

}  // namespace brume
