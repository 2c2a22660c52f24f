#pragma once
// glTF 2.0 (.gltf / .glb) -> Scene, through tinygltf. Tolerant of broken files: what can be repaired is repaired and
// reported in Scene::warnings; what cannot ends in SceneLoadResult::error naming the file and the problem.
#include "scene/scene_source.h"

#include <cstddef>
#include <string>
#include <vector>

namespace shadowlab {

// Loads the default scene (or scene 0, or every root node when the file has no scenes). The format is chosen by the
// file's magic ("glTF" = binary), so *.gltf.json copies load too. Never throws.
SceneLoadResult loadGltfScene(const std::string& path);

// The same from a file's bytes (the fuzzer's entry): `label` names it in messages and becomes the scene's name;
// relative buffer and image URIs resolve against `baseDir`.
SceneLoadResult loadGltfSceneFromMemory(const std::vector<unsigned char>& bytes, const std::string& label,
                                        const std::string& baseDir);

// Past this many mesh instances a file is refused: a node listed twice by each of 22 ancestors is 4 million copies.
inline constexpr std::size_t kMaxInstances = 100'000;

}  // namespace shadowlab
