#pragma once
// The accuracy meter's G-buffer pass: draws the scene with the main pass's camera, vertex shader, depth state,
// draw order and alpha test, writing (draw, triangle) ids; then rebuilds each pixel's point and geometric normal in
// double precision by intersecting its camera ray with that triangle (exact for any world coordinates).
#include "frame/gpu_scene.h"
#include "gl/gl_objects.h"
#include "gl/texture_read_back.h"
#include "reference/surface_samples.h"

#include <glm/ext/matrix_double4x4.hpp>

#include <map>
#include <utility>

namespace shadowlab {

class GBufferPass {
public:
    // Needs a current GL context; throws std::runtime_error if the shaders do not build.
    GBufferPass();

    // viewProjection: render-origin-relative, as the Renderer builds it. Returns "" or why the target failed.
    std::string render(const GpuScene& scene, const glm::dmat4& viewProjection, int width, int height,
                       const glm::dvec3& cameraPosition, SurfaceSamples& out);

    // Where the last render's wall time went (the accuracy cost's G-buffer line breaks down into these).
    struct Timings {
        double drawMs = 0.0;      // issuing the draws (and any program built on first use)
        double readBackMs = 0.0;  // waiting for the GPU and copying the ids
        double rebuildMs = 0.0;   // the double-precision points and normals, on every core
    };
    const Timings& lastTimings() const { return timings_; }

private:
    struct Program {
        gl::Program program;
        GLint viewProjection, model, normalMatrix, uvTransform, drawId, alphaFactor, alphaCutoff, baseColorTexture;
    };
    const Program& program(bool alphaMask, bool alphaTexture);
    // Each pixel's point and normal from its read-back (draw + 1, triangle) ids, on every core.
    void rebuild(const GpuScene& scene, const glm::dmat4& viewProjection, int width, int height,
                 const glm::dvec3& cameraPosition, const GLuint* ids, SurfaceSamples& out) const;
    std::string ensureTarget(int width, int height);

    std::map<std::pair<bool, bool>, Program> programs_;
    gl::Texture ids_;
    gl::Renderbuffer depth_;
    gl::Framebuffer framebuffer_;
    gl::TextureReadBack readBack_;
    int width_ = 0;
    int height_ = 0;
    Timings timings_;
};

}  // namespace shadowlab
