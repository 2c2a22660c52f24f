#pragma once
// glTF 2.0 (.gltf / .glb) -> Scene, through tinygltf. Tolerant of broken files: what can be repaired is repaired and
// reported in Scene::warnings; what cannot ends in SceneLoadResult::error naming the file and the problem.
#include "scene/scene_source.h"

#include <string>

namespace shadowlab {

// Loads the default scene (or scene 0, or every root node when the file has no scenes). The format is chosen by the
// file's magic ("glTF" = binary), so *.gltf.json copies load too. Never throws.
SceneLoadResult loadGltfScene(const std::string& path);

}  // namespace shadowlab
