#pragma once
// glTF animations -> Scene::animations: node translation, rotation and scale channels with LINEAR, STEP and
// CUBICSPLINE samplers. Each channel is checked (its node exists and has no matrix, the sampler's input times are
// finite and strictly increasing, the output holds one value per key (three with CUBICSPLINE), every value finite);
// an animation with a channel that fails is skipped with a warning naming the animation, the channel and the cause,
// and the rest of the file loads. Morph-target weights are not played (counted in one warning).
#include "scene/gltf_common.h"
#include "scene/node_animation.h"

#include <vector>

namespace shadowlab::gltf {

// The file's playable animations. Key data counts against `budget` (a refusal leaves budget.exceeded set).
std::vector<Animation> importAnimations(const tg::Model& model, DecodeBudget& budget, const Warn& warn);

// 1 for every node of the file some channel of `animations` targets (indexed by glTF node).
std::vector<char> animatedNodes(const tg::Model& model, const std::vector<Animation>& animations);

}  // namespace shadowlab::gltf
