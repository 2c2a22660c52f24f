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
    : target_(camera.target), fovYDeg_(camera.fovYDeg), orthoHalfHeight_(camera.orthoHalfHeight) {
    setSceneBounds(sceneBounds);
    glm::dvec3 offset = camera.position - camera.target;
    distance_ = glm::length(offset);
    if (!(distance_ > 1e-9) || !std::isfinite(distance_)) {
        offset = glm::dvec3(0.0, 0.0, 1.0);
        distance_ = sceneRadius_ * 3.0;
    }
    setOffsetDirection(offset / glm::length(offset));
    clampDistance();
}

void OrbitCamera::setOffsetDirection(const glm::dvec3& dir) {
    yaw_ = std::atan2(dir.x, dir.z);
    pitch_ = std::clamp(std::asin(std::clamp(dir.y, -1.0, 1.0)), -maxPitch(), maxPitch());
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
    camera.orthoHalfHeight = orthoHalfHeight_;
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
    const double worldPerPixel = toCamera().worldPerPixel(distance_, viewHeight);
    const glm::dvec3 back = offsetDirection(yaw_, pitch_);  // target -> eye
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0.0, 1.0, 0.0), back));
    const glm::dvec3 up = glm::cross(back, right);
    // The scene moves with the mouse, so the camera moves the other way (screen y grows downward).
    target_ += (-right * dxPixels + up * dyPixels) * worldPerPixel;
}

void OrbitCamera::zoom(double wheelSteps) {
    const double before = distance_;
    distance_ *= std::pow(kZoomPerWheelStep, wheelSteps);
    clampDistance();
    orthoHalfHeight_ *= distance_ / before;  // an orthographic view zooms by its size (distance alone shows nothing)
}

void OrbitCamera::look(double dxPixels, double dyPixels) {
    // The eye stays: turning the view the way an orbit turns the eye, then putting the target back in front.
    const glm::dvec3 eyeBefore = eye();
    yaw_ = std::remainder(yaw_ - dxPixels * kRadiansPerPixel, 2.0 * M_PI);
    pitch_ = std::clamp(pitch_ + dyPixels * kRadiansPerPixel, -maxPitch(), maxPitch());
    target_ = eyeBefore - offsetDirection(yaw_, pitch_) * distance_;
}

void OrbitCamera::fly(const glm::dvec3& axes, double seconds, double speedFactor) {
    if (!(seconds > 0.0) || !std::isfinite(seconds)) return;
    const ViewBasis basis = viewBasis(-offsetDirection(yaw_, pitch_));
    const glm::dvec3 a = glm::clamp(axes, glm::dvec3(-1.0), glm::dvec3(1.0));
    target_ += (basis.right * a.x + basis.up * a.y + basis.forward * a.z) * (flySpeed() * speedFactor * seconds);
}

void OrbitCamera::setPivot(const glm::dvec3& point) {
    const glm::dvec3 eyeNow = eye();
    const glm::dvec3 offset = eyeNow - point;
    const double length = glm::length(offset);
    if (!(length > 1e-9 * sceneRadius_) || !std::isfinite(length)) return;  // the eye itself: no direction
    setOffsetDirection(offset / length);
    // A clamped pitch would move the eye: keep the eye, so the pivot lies on the view axis at the point's distance.
    distance_ = length;
    target_ = eyeNow - offsetDirection(yaw_, pitch_) * distance_;
}

void OrbitCamera::frame(const Scene& scene, double aspect) {
    setSceneBounds(scene.bounds);
    Camera camera = toCamera();
    frameScene(camera, scene, aspect);
    target_ = camera.target;
    distance_ = glm::length(camera.position - camera.target);
    clampDistance();
    // Orthographic: the height the perspective framing shows at the target's depth.
    if (orthoHalfHeight_ > 0.0) orthoHalfHeight_ = distance_ * std::tan(glm::radians(fovYDeg_) * 0.5);
}

}  // namespace shadowlab
