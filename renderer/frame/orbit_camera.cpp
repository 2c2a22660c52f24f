#include "frame/orbit_camera.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// Unit vector from the target toward the eye.
glm::dvec3 offsetDirection(double yaw, double pitch) {
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

double maxPitch() { return glm::radians(OrbitCamera::kMaxPitchDeg); }

}  // namespace

OrbitCamera::OrbitCamera(const Camera& camera, const Bounds& sceneBounds)
    : target_(camera.target), fovYDeg_(camera.fovYDeg) {
    setSceneBounds(sceneBounds);
    glm::dvec3 offset = camera.position - camera.target;
    distance_ = glm::length(offset);
    if (!(distance_ > 1e-9) || !std::isfinite(distance_)) {
        offset = glm::dvec3(0.0, 0.0, 1.0);
        distance_ = sceneRadius_ * 3.0;
    }
    const glm::dvec3 dir = offset / glm::length(offset);
    yaw_ = std::atan2(dir.x, dir.z);
    pitch_ = std::clamp(std::asin(std::clamp(dir.y, -1.0, 1.0)), -maxPitch(), maxPitch());
    clampDistance();
}

void OrbitCamera::setSceneBounds(const Bounds& bounds) {
    bounds_ = bounds;
    sceneRadius_ = bounds.empty ? 1.0 : std::max(double(bounds.radius()), 1e-3);
}

void OrbitCamera::clampDistance() {
    distance_ = std::clamp(distance_, kMinDistanceRadii * sceneRadius_, kMaxDistanceRadii * sceneRadius_);
}

glm::dvec3 OrbitCamera::eye() const { return target_ + offsetDirection(yaw_, pitch_) * distance_; }

Camera OrbitCamera::toCamera() const {
    Camera camera;
    camera.position = eye();
    camera.target = target_;
    camera.fovYDeg = fovYDeg_;
    fitDepthRange(camera, bounds_);
    return camera;
}

void OrbitCamera::orbit(double dxPixels, double dyPixels) {
    // Dragging right swings the eye left around the target, so the scene turns right under the mouse.
    yaw_ -= dxPixels * kRadiansPerPixel;
    yaw_ = std::remainder(yaw_, 2.0 * M_PI);
    pitch_ = std::clamp(pitch_ + dyPixels * kRadiansPerPixel, -maxPitch(), maxPitch());
}

void OrbitCamera::pan(double dxPixels, double dyPixels, int viewHeight) {
    if (viewHeight < 1) return;
    // World size of one pixel at the target's depth: the visible height there is 2 d tan(fov/2).
    const double worldPerPixel = 2.0 * distance_ * std::tan(glm::radians(fovYDeg_) * 0.5) / viewHeight;
    const glm::dvec3 back = offsetDirection(yaw_, pitch_);  // target -> eye
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0.0, 1.0, 0.0), back));
    const glm::dvec3 up = glm::cross(back, right);
    // The scene moves with the mouse, so the camera moves the other way (screen y grows downward).
    target_ += (-right * dxPixels + up * dyPixels) * worldPerPixel;
}

void OrbitCamera::zoom(double wheelSteps) {
    distance_ *= std::pow(kZoomPerWheelStep, wheelSteps);
    clampDistance();
}

void OrbitCamera::frame(const Scene& scene, double aspect) {
    setSceneBounds(scene.bounds);
    Camera camera = toCamera();
    frameScene(camera, scene, aspect);
    target_ = camera.target;
    distance_ = glm::length(camera.position - camera.target);
    clampDistance();
}

}  // namespace shadowlab
