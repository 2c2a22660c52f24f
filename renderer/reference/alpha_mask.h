#pragma once
// The alpha rule the renderer's shadow pass applies to glTF MASK casters, on the CPU for the reference's occlusion
// filter: base-colour alpha (bilinear, mip 0, repeat wrap as the GPU textures have) times the factor, against the
// cutoff. Barycentric (u, v) follow Embree's convention: p = (1-u-v) p0 + u p1 + v p2.
#include "scene/scene.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace shadowlab {

class AlphaMask {
public:
    // uvs and indices of the mesh; image may be null (alpha = factor everywhere).
    AlphaMask(const Material& material, const Image* image, const std::vector<glm::vec2>& uvs,
              const std::vector<std::uint32_t>& indices);

    // Whether the caster is opaque (alpha >= cutoff) at barycentric (u, v) of triangle `primitive`.
    bool opaqueAt(unsigned primitive, float u, float v) const;

    // Base-colour alpha x factor at a texture coordinate (already through the material's uv transform).
    float alphaAt(const glm::vec2& uv) const;

private:
    const Image* image_;
    const std::vector<glm::vec2>* uvs_;
    const std::vector<std::uint32_t>* indices_;
    glm::mat3 uvTransform_;
    float factor_;
    float cutoff_;
};

}  // namespace shadowlab
