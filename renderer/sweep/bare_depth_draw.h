#pragma once
// The raster limit beside the cost: the same triangles as the shadow pass, drawn the barest way a GPU allows — one
// buffer of world-space (render-origin-relative) triangles, one draw call, depth only, no bias, no culling, no alpha
// test, no per-caster culling — into a map of the same size and format. A sweep reports each shadow pass as a
// multiple of this draw. Needs a current GL 4.5 context.
#include "gl/gl_objects.h"
#include "scene/scene.h"
#include "settings/settings.h"
#include "shadow/shadow_map.h"
#include "timing/pass_timer.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>

#include <string>
#include <vector>

namespace shadowlab {

struct BareDrawTiming {
    bool ok = false;
    std::string error;
    int resolution = 0;
    DepthFormat format = DepthFormat::D32F;
    glm::dmat4 lightViewProjection{1.0};  // the light it was drawn from (a light axis gets one draw per light)
    double ms = 0.0;            // median of the timed draws (same source as the renderer's passes)
    double wallMsPerDraw = 0.0;
};

class BareDepthDraw {
public:
    // Flattens every instance of the scene into world space relative to `origin` (the renderer's render origin);
    // with `instances` (one flag per Scene::instances entry) only those flagged: the casters one view holds.
    BareDepthDraw(const Scene& scene, const glm::dvec3& origin, TimingSource source,
                  const std::vector<char>* instances = nullptr);

    // Times `frames` draws (after the warm-up of timed_frames.h) through the light's view-projection (relative to
    // the same origin) into a resolution² map of this format.
    BareDrawTiming time(const glm::dmat4& lightViewProjection, int resolution, DepthFormat format, int maxTextureSize,
                        int frames);

    std::size_t triangles() const { return std::size_t(vertexCount_ / 3); }

private:
    gl::Program program_;
    GLint lightViewProjection_ = -1;
    gl::Buffer vertices_;
    gl::Buffer transform_;  // one identity matrix (the transform buffer the shader reads)
    gl::Buffer drawIndex_;  // one 0
    gl::VertexArray vao_;
    GLsizei vertexCount_ = 0;
    PassTimer timer_;
    ShadowMap map_;
};

}  // namespace shadowlab
