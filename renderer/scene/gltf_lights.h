#pragma once
// KHR_lights_punctual: a node's light placed in the world (position from the node's origin, direction its -Z).
#include "scene/gltf_common.h"
#include "scene/scene.h"

#include <glm/mat4x4.hpp>

#include <optional>

namespace shadowlab::gltf {

// The light node `nodeIndex` carries, under its world transform; nullopt when it has none or it is unusable (warned).
std::optional<SceneLight> importLight(const tg::Model& model, int nodeIndex, const glm::dmat4& world, const Warn& warn);

}  // namespace shadowlab::gltf
