#pragma once
// The camera as the shadow views see it: what a cascade fits to and what picks a cascade for a pixel. Built from
// the frame's Camera and view size (frame/camera.h: viewCameraOf); plain values here so the views stay free of GL.
#include <glm/ext/vector_double3.hpp>

#include <optional>

namespace shadowlab {

// A span of depths in front of the camera, along its viewing direction.
struct ViewDepths {
    double nearest = 0.0, farthest = 0.0;
    bool operator==(const ViewDepths&) const = default;
};

struct ViewCamera {
    glm::dvec3 eye{0.0};                       // render-origin-relative
    glm::dvec3 forward{0.0, 0.0, -1.0};        // unit viewing direction
    glm::dvec3 right{1.0, 0.0, 0.0}, up{0.0, 1.0, 0.0};  // unit, the view's axes
    double tanHalfFovY = 0.41421356237309503;  // 45 degrees
    double aspect = 1.0;                       // width / height of the view
    double nearPlane = 0.05;
    double farPlane = 200.0;
    // The nearest and farthest depth of what the camera sees, as the depth-bounds pass measured it (this frame's or
    // the previous one's, projection.depthBounds); nullopt: not measured. farthest < nearest: nothing was seen.
    std::optional<ViewDepths> seenDepths;

    // How far in front of the camera p lies, along its viewing direction (what the cascade splits measure).
    double depthOf(const glm::dvec3& p) const;
    bool finite() const;
};

}  // namespace shadowlab
