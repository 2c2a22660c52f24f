#pragma once
// The main view's camera, built in double precision relative to the render origin.
#include "scene/scene.h"
#include "settings/settings.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>

namespace shadowlab {

struct Camera {
    glm::dvec3 position{8.0, 6.0, 10.0};  // world
    glm::dvec3 target{0.0};               // world
    double fovYDeg = 45.0;
    double nearPlane = 0.05;
    double farPlane = 200.0;

    // Render-origin-relative view and projection for an aspect ratio (width / height).
    glm::dmat4 view(const glm::dvec3& origin) const;
    glm::dmat4 projection(double aspect) const;
};

// The camera the settings ask for: their position/target, or one framing the scene's bounds from the scene's
// preferred side (camera.autoFrame). Near/far always follow the scene's size so depth precision suits it.
Camera cameraFor(const CameraSettings& settings, const Scene& scene);

// Sets near/far so the whole of `bounds` lies between them from the camera's position, with the near plane as far
// out as that allows (depth precision follows the scene's size).
void fitDepthRange(Camera& camera, const Bounds& bounds);

}  // namespace shadowlab
