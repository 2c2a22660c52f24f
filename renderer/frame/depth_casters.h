#pragma once
// Depth-only drawing of a list of a GpuScene's draws, shared by the shadow pass and the depth-bounds prepass: one
// vertex shader (shadow_depth.vert.glsl), no fragment stage for opaque draws, shadow_alpha.frag.glsl for
// alpha-tested (MASK) ones. The draws go out batched (frame/draw_batches.h): one multi-draw call per face-cull
// state for the opaque draws, one per material and cull state for the alpha-tested ones.
#include "frame/draw_batches.h"
#include "frame/face_culling.h"
#include "frame/gpu_scene.h"
#include "gl/gl_objects.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace shadowlab {

struct DepthCastersDrawn {
    int drawCalls = 0;  // multi-draw calls: one per group of draws sharing their state
    int alphaTested = 0;
    std::size_t triangles = 0;
};

class DepthCasters {
public:
    DepthCasters();  // needs a current GL 4.5 context; throws std::runtime_error if a shader does not build

    // Draws `draws` (indices into scene.draws()) into the bound framebuffer with the caller's depth state, through
    // `viewProjection` (render-origin-relative world to clip); cullOf gives a draw's face culling from its
    // material (null: glTF's default) and mirrored flag. Leaves face culling at its defaults (resetFaceCulling).
    DepthCastersDrawn draw(const GpuScene& scene, const std::vector<std::uint32_t>& draws,
                           const glm::mat4& viewProjection,
                           const std::function<FaceCullState(const Material*, bool mirrored)>& cullOf);

private:
    // A program with its uniform locations, looked up once (-1 where the program lacks one).
    struct Program {
        gl::Program program;
        GLint viewProjection = -1, uvTransform = -1, alphaFactor = -1, alphaCutoff = -1, baseColor = -1;
        explicit Program(gl::Program built);
    };
    // Built when a MASK material is first drawn: a scene without one compiles no fragment stage here.
    const Program& alphaProgram(bool textured);

    Program opaque_;                        // vertex stage only: no fragment work
    std::optional<Program> alphaFactor_;    // MASK material without a texture
    std::optional<Program> alphaTextured_;  // MASK material with a base-colour texture
    DrawBatches batches_;
};

}  // namespace shadowlab
