#pragma once
// The editor's view camera: orbits around a target (yaw / pitch, pitch kept away from straight up and down), pans in
// the view plane so the point under the cursor follows the mouse, zooms multiplicatively, and frames the scene the
// way auto-framing does (the F key). Fly mode moves the eye instead: it looks around from where it stands and
// travels along its own axes at a speed that follows the scene's size, per second of the caller's clock (so the
// distance covered does not depend on the frame rate); the pivot then travels with it. Converts to and from the
// renderer's Camera (an orthographic one stays orthographic; zoom scales its height). No GL.
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

    // Fly mode. A mouse drag of (dx, dy) pixels turns the view around the eye (right looks right, down looks down);
    // the pivot stays at its distance in front of the eye.
    void look(double dxPixels, double dyPixels);
    // Travels `seconds` along the view's axes: `axes` = (right, up, forward), each in [-1, 1] (WASD, Q/E), at
    // flySpeed() times `speedFactor` world units per second. Eye and pivot move together.
    void fly(const glm::dvec3& axes, double seconds, double speedFactor = 1.0);
    // World units per second at speed factor 1: kFlyRadiiPerSecond of the scene's radius.
    double flySpeed() const { return kFlyRadiiPerSecond * sceneRadius_; }
    static constexpr double kFlyRadiiPerSecond = 0.2;

    // Orbits now turn around `point` (a surface picked in the view): the eye stays, the view turns to face it.
    void setPivot(const glm::dvec3& point);

    glm::dvec3 target() const { return target_; }
    glm::dvec3 eye() const;
    double distance() const { return distance_; }
    double yawRad() const { return yaw_; }
    double pitchRad() const { return pitch_; }

    static constexpr double kMinDistanceRadii = 0.01;
    static constexpr double kMaxDistanceRadii = 100.0;

private:
    void setSceneBounds(const Bounds& bounds);
    // Yaw and pitch from a unit vector pointing from the target to the eye (pitch clamped).
    void setOffsetDirection(const glm::dvec3& toEye);
    void clampDistance();

    glm::dvec3 target_{0.0};
    double distance_ = 1.0;
    double yaw_ = 0.0;    // around +y; 0 = eye on +z of the target
    double pitch_ = 0.0;  // above the target's horizontal plane
    double fovYDeg_ = 45.0;
    double orthoHalfHeight_ = 0.0;  // > 0: orthographic (a file's camera); scales with the distance
    Bounds bounds_;
    double sceneRadius_ = 1.0;
};

}  // namespace shadowlab
