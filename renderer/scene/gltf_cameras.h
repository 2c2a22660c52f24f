#pragma once
// glTF cameras: a node's camera placed in the world (position from the node's origin, viewing along its -Z), its
// projection checked value by value. A camera the renderer could not use is refused alone, with a warning naming
// its index; the rest of the file loads.
#include "scene/gltf_common.h"
#include "scene/scene.h"

#include <glm/ext/matrix_double4x4.hpp>

#include <optional>

namespace shadowlab::gltf {

// The camera node `nodeIndex` carries, under its world transform; nullopt when it has none or it is refused (warned).
std::optional<SceneCamera> importCamera(const tg::Model& model, int nodeIndex, const glm::dmat4& world,
                                        const Warn& warn);

}  // namespace shadowlab::gltf
