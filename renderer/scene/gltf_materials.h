#pragma once
// glTF materials -> Scene materials. Only what shadows need: alpha mode and cutoff, base colour factor and texture
// (with its sampler wrap, texCoord and KHR_texture_transform). Images are decoded after the node walk, only for the
// materials drawn, once each.
#include "scene/gltf_common.h"
#include "scene/gltf_images.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace shadowlab::gltf {

// Appends one Material per glTF material to scene.materials (same indices), without images yet. Returns, by
// material, the glTF image its base colour texture names (-1: none). Broken parts fall back to defaults with a
// warning.
std::vector<int> importMaterials(const tg::Model& model, Scene& scene, const Warn& warn);

// Sets baseColorImage of the materials the scene's instances draw, decoding each image they use once (however many
// materials, textures or image entries name it) into scene.images. Every image's decoded size is read from its
// header and counted against `budget` before any is decoded; an image past the texture limit or unreadable is a
// warning (alpha from the factor only). "" or, when the images would pass the budget, why the scene is refused.
std::string importMaterialImages(const tg::Model& model, const EncodedImages& images,
                                 const std::vector<int>& baseColorSources, Scene& scene, DecodeBudget& budget,
                                 const Warn& warn);

}  // namespace shadowlab::gltf
