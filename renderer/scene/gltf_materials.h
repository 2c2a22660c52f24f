#pragma once
// glTF materials -> Scene materials. Only what shadows need: alpha mode and cutoff, base colour factor and texture
// (with its sampler wrap, texCoord and KHR_texture_transform). Images are decoded on first use, once each.
#include "scene/gltf_common.h"
#include "scene/gltf_images.h"
#include "scene/scene.h"

namespace shadowlab::gltf {

// Appends one Material per glTF material to scene.materials (same indices) and the base colour images they use to
// scene.images. Broken parts fall back to defaults with a warning.
void importMaterials(const tg::Model& model, const EncodedImages& images, Scene& scene, const Warn& warn);

}  // namespace shadowlab::gltf
