#include "frame/camera.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

glm::dmat4 Camera::view(const glm::dvec3& origin) const {
    glm::dvec3 forward = target - position;
    if (glm::length(forward) < 1e-12) forward = glm::dvec3(0.0, 0.0, -1.0);
    forward = glm::normalize(forward);
    // Looking straight up or down: lookAt's up=(0,1,0) would be parallel, so use -z as up there.
    const glm::dvec3 up = std::abs(forward.y) > 0.999 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
    return glm::lookAt(position - origin, position - origin + forward, up);
}

glm::dmat4 Camera::projection(double aspect) const {
    return glm::perspective(glm::radians(fovYDeg), std::max(aspect, 1e-6), nearPlane, farPlane);
}

Camera cameraFor(const CameraSettings& settings, const Scene& scene) {
    const Bounds& bounds = scene.bounds;
    Camera camera;
    camera.fovYDeg = settings.fovYDeg;
    const glm::dvec3 center = bounds.empty ? glm::dvec3(0.0) : glm::dvec3(bounds.center());
    const double radius = bounds.empty ? 1.0 : std::max(double(bounds.radius()), 1e-3);
    if (settings.autoFrame) {
        // A three-quarter view from above (by default across the default light, so shadows fall to the side, not
        // behind the objects), far enough back that the bounding sphere fits the vertical field of view.
        const glm::dvec3 viewDirection = glm::normalize(glm::dvec3(scene.viewDirection));
        const double distance = radius / std::sin(glm::radians(settings.fovYDeg) * 0.5);
        camera.target = center;
        camera.position = center + viewDirection * distance;
    } else {
        camera.position = settings.position;
        camera.target = settings.target;
    }
    fitDepthRange(camera, bounds);
    return camera;
}

void fitDepthRange(Camera& camera, const Bounds& bounds) {
    const glm::dvec3 center = bounds.empty ? glm::dvec3(0.0) : glm::dvec3(bounds.center());
    const double radius = bounds.empty ? 1.0 : std::max(double(bounds.radius()), 1e-3);
    const double reach = glm::length(camera.position - center) + radius;
    camera.farPlane = reach * 1.05;
    camera.nearPlane = std::max(camera.farPlane * 1e-4, 1e-4);
}

}  // namespace shadowlab
