#pragma once
// A Scene uploaded to the GPU: one vertex buffer, one index buffer, a draw per instance, the alpha textures of
// MASK materials, and a transform buffer holding every draw's model matrix (read by the depth passes' one vertex
// shader, shaders/shadow_depth.vert.glsl, so a view's casters go out in a few multi-draw calls). Model matrices are
// made relative to a render origin in double precision. When only instance transforms change (an animation step),
// updateTransforms rewrites the matrices that moved and uploads nothing else.
#include "gl/gl_objects.h"
#include "scene/scene.h"

#include <glm/ext/vector_double3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

// The transform buffer's shader-storage binding: a std430 block `DrawTransforms { mat4 drawModel[]; }` indexed by
// draw (bindDrawTransformsBlock points a program's block here).
inline constexpr GLuint kDrawTransformsBinding = 10;
// The vertex attribute that carries a draw's index into the transform buffer: an instanced attribute (divisor 1)
// over a buffer holding 0..N-1, so a draw command's baseInstance selects its draw (GL 4.5 has no gl_DrawID or
// gl_BaseInstance in core). Locations 0..2 are position, normal and uv (main.vert.glsl).
inline constexpr GLuint kDrawIndexAttribute = 3;

// Points a program's DrawTransforms block (if it has one) at kDrawTransformsBinding.
void bindDrawTransformsBlock(GLuint program);

struct GpuDraw {
    GLsizei indexCount = 0;
    std::size_t firstIndexByte = 0;
    GLint baseVertex = 0;
    glm::mat4 model{1.0f};           // object -> render-origin-relative world (also the transform buffer's entry)
    glm::mat3 normalMatrix{1.0f};
    bool mirrored = false;           // negative determinant: front faces are clockwise
    int material = -1;
    glm::vec3 boundsCenter{0.0f};    // render-origin-relative bounding sphere (finite vertices only)
    float boundsRadius = 0.0f;
    bool hasFiniteBounds = false;
    std::size_t instance = 0;        // its Scene::instances entry
    bool casts = true;               // drawn into shadow maps (casters.excluded; see setCasting)
};

// What the last upload (the constructor or updateTransforms) sent to the GPU.
struct SceneUpload {
    bool geometry = false;           // vertices, indices and textures: the scene uploaded whole
    std::size_t geometryBytes = 0;
    std::size_t transformBytes = 0;  // model matrices written to the transform buffer
    int drawsMoved = 0;              // draws whose model matrix changed (every draw on a geometry upload)
    std::vector<std::size_t> moved;  // updateTransforms: those draws (indices into GpuScene::draws()), in order
    std::string describe() const;    // "geometry uploaded, N bytes ..." or "transforms updated, N bytes ..."
};

class GpuScene {
public:
    GpuScene(const Scene& scene, const glm::dvec3& origin);

    // Binds the vertex array and the transform buffer (at kDrawTransformsBinding).
    void bind() const;
    const std::vector<GpuDraw>& draws() const { return draws_; }
    // Which draws cast shadows, from a flag per Scene::instances entry (scene/scene_casters.h).
    void setCasting(const std::vector<char>& castingInstances);
    // The alpha texture of a material (0 when it has none).
    GLuint materialTexture(int material) const;
    const Scene& scene() const { return *scene_; }
    const glm::dvec3& origin() const { return origin_; }

    // Whether `scene` has this upload's geometry, so that only its transforms may differ (scene/scene_fingerprint.h):
    // the same meshes (vertices, indices, material), materials' depth values, images and instance -> mesh list. A
    // cheap check of the data's addresses first (layoutFingerprint: an in-place edit calls Renderer::sceneChanged),
    // else of the contents (geometryFingerprint: a posed copy of a scene).
    bool sameGeometry(const Scene& scene) const;
    // geometryFingerprint of the uploaded scene: what the shadow maps' contents depend on besides the transforms.
    std::size_t geometryFingerprint() const { return geometry_; }
    // For a scene of the same geometry (sameGeometry): takes its instance transforms relative to `origin`, updates each
    // draw's matrices, bounds and mirrored flag, and rewrites only the transform buffer's entries that changed.
    // `scene` replaces the one drawn (it must outlive this GpuScene, as the constructor's does).
    const SceneUpload& updateTransforms(const Scene& scene, const glm::dvec3& origin);
    const SceneUpload& lastUpload() const { return lastUpload_; }
    // Bytes the last upload sent (geometry and transforms).
    std::size_t uploadedBytes() const { return lastUpload_.geometryBytes + lastUpload_.transformBytes; }

private:
    void placeDraw(const Instance& instance, const glm::dmat4& toOrigin, GpuDraw& draw) const;

    const Scene* scene_;
    glm::dvec3 origin_;
    gl::VertexArray vao_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::Buffer transforms_;   // mat4 per draw, in draws_ order
    gl::Buffer drawIndices_;  // 0..N-1: kDrawIndexAttribute's source
    std::vector<gl::Texture> imageTextures_;  // one per Scene::images entry (empty handle when invalid)
    std::vector<Bounds> meshBoxes_;           // each mesh's object-space box (finite vertices)
    std::vector<GpuDraw> draws_;
    std::size_t layout_ = 0;                  // sameGeometry's cheap key (layoutFingerprint)
    std::size_t geometry_ = 0;                // and its content key (geometryFingerprint)
    SceneUpload lastUpload_;
};

}  // namespace shadowlab
