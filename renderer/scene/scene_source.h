#pragma once
// Where a scene comes from: "builtin:NAME" (procedural, see builtin_scenes.h) or a .gltf / .glb file.
#include "scene/scene.h"

#include <optional>
#include <string>

namespace shadowlab {

struct SceneLoadResult {
    std::optional<Scene> scene;
    std::string error;  // empty on success; otherwise names the file (or spec) and what is wrong
    bool ok() const { return scene.has_value(); }
};

inline constexpr const char* kBuiltinPrefix = "builtin:";
inline constexpr const char* kDefaultSceneSpec = "builtin:textbook";

// spec = "builtin:NAME" or a path to a .gltf / .glb file. Never throws.
SceneLoadResult loadScene(const std::string& spec);

}  // namespace shadowlab
