#pragma once
// The depth-bounds pass (projection.depthBounds): the nearest and farthest view depth of what the camera sees, from
// the camera's depth buffer reduced on the GPU (gl/depth_range_reduction.h), for the cascades' splits
// (views/depth_bounds.h).
//  - sameFrame: a depth-only prepass of the whole scene from the camera, reduced and read back before the shadow
//    views are planned. Read back (not an indirect path) because the planner runs on the CPU: it culls casters per
//    cascade, snaps the stable fit to texels and decides which cascades re-render; the read-back waits for the GPU
//    (the prepass and the reduction) once per frame.
//  - previousFrame: the depth the main pass already wrote is reduced after it; the result is read when the next
//    frame plans its views (by then the GPU has finished the frame before, so the read does not wait; if the GPU is
//    more than a frame behind it waits rather than use older bounds). No extra draw; the bounds are a frame late.
#include "frame/depth_casters.h"
#include "frame/gpu_scene.h"
#include "frame/render_target.h"
#include "gl/depth_range_reduction.h"
#include "gl/gl_objects.h"
#include "views/view_camera.h"

#include <glm/ext/matrix_double4x4.hpp>

#include <optional>

namespace shadowlab {

class DepthBoundsPass {
public:
    DepthBoundsPass();  // needs a current GL 4.5 context; throws std::runtime_error if a shader does not build

    // sameFrame: draws the scene's depth from the camera into `target` (the main pass clears it after), reduces it
    // and reads the result back. viewProjection / projection: the camera's (render-origin-relative).
    ViewDepths measureNow(const GpuScene& scene, const glm::dmat4& viewProjection, const glm::dmat4& projection,
                          RenderTarget& target);
    // previousFrame: starts the reduction of the depth the main pass left in `target`; collect() reads it.
    void reduceMainDepth(const glm::dmat4& projection, RenderTarget& target);
    // The last reduceMainDepth's result; nullopt when none is pending.
    std::optional<ViewDepths> collect();

private:
    void drawDepth(const GpuScene& scene, const glm::dmat4& viewProjection, RenderTarget& target);
    ViewDepths toViewDepths(const std::optional<WrittenDepths>& written, const glm::dmat4& projection) const;

    DepthCasters casters_;  // the shadow pass's depth drawing, from the camera
    DepthRangeReduction reduction_;
    glm::dmat4 pendingProjection_{1.0};  // the projection of the pending reduction's depth
};

}  // namespace shadowlab
