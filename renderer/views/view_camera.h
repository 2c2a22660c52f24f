#pragma once
// The camera as the shadow views see it: what a cascade fits to and what picks a cascade for a pixel. Built from
// the frame's Camera and view size (frame/camera.h: viewCameraOf); plain values here so the views stay free of GL.
#include <glm/ext/vector_double3.hpp>

namespace shadowlab {

struct ViewCamera {
    glm::dvec3 eye{0.0};                       // render-origin-relative
    glm::dvec3 forward{0.0, 0.0, -1.0};        // unit viewing direction
    glm::dvec3 right{1.0, 0.0, 0.0}, up{0.0, 1.0, 0.0};  // unit, the view's axes
    double tanHalfFovY = 0.41421356237309503;  // 45 degrees
    double aspect = 1.0;                       // width / height of the view
    double nearPlane = 0.05;
    double farPlane = 200.0;

    // How far in front of the camera p lies, along its viewing direction (what the cascade splits measure).
    double depthOf(const glm::dvec3& p) const;
    bool finite() const;
};

}  // namespace shadowlab
