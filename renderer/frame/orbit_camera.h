#pragma once
// The editor's view camera: orbits around a target (yaw / pitch, pitch kept away from straight up and down), pans in
// the view plane so the point under the cursor follows the mouse, zooms multiplicatively, and frames the scene the
// way auto-framing does (the F key). Converts to and from the renderer's Camera. No GL.
#include "frame/camera.h"
#include "scene/scene.h"

#include <glm/ext/vector_double3.hpp>

namespace shadowlab {

class OrbitCamera {
public:
    static constexpr double kRadiansPerPixel = 0.008;  // orbit speed of a mouse drag
    static constexpr double kMaxPitchDeg = 85.0;       // |pitch| limit: the view's up vector stays well defined
    static constexpr double kZoomPerWheelStep = 0.85;  // distance factor per wheel step toward the target

    // Takes the camera's eye, target and field of view; `sceneBounds` sets the zoom limits and near/far planes.
    OrbitCamera(const Camera& camera, const Bounds& sceneBounds);

    // Near and far follow the scene's size and the eye's distance, as cameraFor does.
    Camera toCamera() const;

    // A mouse drag of (dx, dy) view pixels (y down): right turns the scene right, down shows it more from above.
    void orbit(double dxPixels, double dyPixels);
    // A mouse drag of (dx, dy) pixels in a view `viewHeight` pixels tall: points at the target's depth follow the
    // mouse exactly.
    void pan(double dxPixels, double dyPixels, int viewHeight);
    // Wheel steps (positive = toward the target). Distance is clamped to [kMinDistanceRadii, kMaxDistanceRadii] times
    // the scene's radius.
    void zoom(double wheelSteps);
    // Keeps the viewing direction and moves so the scene's vertices fill the view as auto-framing does (frameScene:
    // the limiting dimension kAutoFrameFill full, centred); orbits then turn around the subject's middle.
    void frame(const Scene& scene, double aspect);

    glm::dvec3 target() const { return target_; }
    glm::dvec3 eye() const;
    double distance() const { return distance_; }
    double yawRad() const { return yaw_; }
    double pitchRad() const { return pitch_; }

    static constexpr double kMinDistanceRadii = 0.01;
    static constexpr double kMaxDistanceRadii = 100.0;

private:
    void setSceneBounds(const Bounds& bounds);
    void clampDistance();

    glm::dvec3 target_{0.0};
    double distance_ = 1.0;
    double yaw_ = 0.0;    // around +y; 0 = eye on +z of the target
    double pitch_ = 0.0;  // above the target's horizontal plane
    double fovYDeg_ = 45.0;
    Bounds bounds_;
    double sceneRadius_ = 1.0;
};

}  // namespace shadowlab
