#pragma once
// A Scene uploaded to the GPU: one vertex buffer, one index buffer, a draw per instance, and the alpha textures of
// MASK materials. Model matrices are made relative to a render origin in double precision.
#include "gl/gl_objects.h"
#include "scene/scene.h"

#include <glm/ext/vector_double3.hpp>

#include <cstdint>
#include <vector>

namespace shadowlab {

struct GpuDraw {
    GLsizei indexCount = 0;
    std::size_t firstIndexByte = 0;
    GLint baseVertex = 0;
    glm::mat4 model{1.0f};           // object -> render-origin-relative world
    glm::mat3 normalMatrix{1.0f};
    bool mirrored = false;           // negative determinant: front faces are clockwise
    int material = -1;
    glm::vec3 boundsCenter{0.0f};    // render-origin-relative bounding sphere (finite vertices only)
    float boundsRadius = 0.0f;
    bool hasFiniteBounds = false;
    std::size_t instance = 0;        // its Scene::instances entry
    bool casts = true;               // drawn into shadow maps (casters.excluded; see setCasting)
};

class GpuScene {
public:
    GpuScene(const Scene& scene, const glm::dvec3& origin);

    void bind() const;
    const std::vector<GpuDraw>& draws() const { return draws_; }
    // Moves the draws to the instances' transforms of `scene`, which has the geometry uploaded (a posed copy, or the
    // same scene posed again: geometryFingerprint equal); returns the draws whose transform changed. Nothing is
    // uploaded: model matrices are per-draw uniforms. The scene must outlive its use, as the constructor's.
    std::vector<std::size_t> updateTransforms(const Scene& scene);
    // Which draws cast shadows, from a flag per Scene::instances entry (scene/scene_casters.h).
    void setCasting(const std::vector<char>& castingInstances);
    // The alpha texture of a material (0 when it has none).
    GLuint materialTexture(int material) const;
    const Scene& scene() const { return *scene_; }
    const glm::dvec3& origin() const { return origin_; }
    std::size_t uploadedBytes() const { return uploadedBytes_; }

private:
    const Scene* scene_;
    glm::dvec3 origin_;
    gl::VertexArray vao_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    std::vector<gl::Texture> imageTextures_;  // one per Scene::images entry (empty handle when invalid)
    std::vector<GpuDraw> draws_;
    std::vector<glm::mat4> transforms_;  // each draw's instance transform as placed
    std::size_t uploadedBytes_ = 0;
};

}  // namespace shadowlab
