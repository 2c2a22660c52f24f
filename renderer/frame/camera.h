#pragma once
// The main view's camera, built in double precision relative to the render origin.
#include "scene/scene.h"
#include "settings/settings.h"
#include "views/view_camera.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>

#include <string>
#include <vector>

namespace shadowlab {

struct Camera {
    glm::dvec3 position{8.0, 6.0, 10.0};  // world
    glm::dvec3 target{0.0};               // world
    double fovYDeg = 45.0;
    double nearPlane = 0.05;
    double farPlane = 200.0;
    // > 0: an orthographic view (a file's orthographic camera), half its height in world units; fovYDeg unused.
    double orthoHalfHeight = 0.0;

    // Render-origin-relative view and projection for an aspect ratio (width / height).
    glm::dmat4 view(const glm::dvec3& origin) const;
    glm::dmat4 projection(double aspect) const;
    // World size of one pixel of a view `heightPixels` tall at `depth` along the viewing direction.
    double worldPerPixel(double depth, int heightPixels) const;

    bool operator==(const Camera&) const = default;
};

// The camera the settings ask for: the scene's camera camera.sceneCamera (its projection and near/far as the file
// gives them, an infinite far plane replaced by the scene's reach; the aspect is `aspect`), else their
// position/target, or (camera.autoFrame) the scene's own viewpoint where it has one, else one looking from the
// scene's preferred side whose view the scene's vertices fill: the projected hull just fits the limiting dimension of
// a view of `aspect` (width / height), with a small margin, centred. The free camera's near/far follow the scene's
// size so depth precision suits it. A sceneCamera the scene lacks (see sceneCameraError) gives the free camera.
Camera cameraFor(const CameraSettings& settings, const Scene& scene, double aspect);

// "" when camera.sceneCamera is -1 or names one of the scene's cameras, else the error naming the key, the index and
// the cameras there are.
std::string sceneCameraError(const CameraSettings& settings, const Scene& scene);

// The view of one of the file's cameras (what cameraFor gives for its index).
Camera sceneCameraView(const SceneCamera& camera, const Bounds& bounds);

// The camera settings that bring `used` back (what a saved preset records): its position, target and fov, with
// `autoFrame` as given (true: auto-framing still decides on load, the recorded values say what it chose here).
CameraSettings recordedCamera(const Camera& used, bool autoFrame);

// The camera as the shadow views see it (what cascades fit to), for a view of `aspect` (width / height),
// render-origin-relative.
ViewCamera viewCameraOf(const Camera& camera, double aspect, const glm::dvec3& origin);

// Share of the view's frame (0..1) reserved for the subject in its limiting dimension when auto-framing.
inline constexpr double kAutoFrameFill = 0.9;

// Moves `camera` (keeping its viewing direction and field of view) so that every point fits a view of `aspect`, the
// points' projection filling kAutoFrameFill of the limiting dimension and centred in both; the target lies on the
// view axis at the points' mean depth. Points are world positions; nothing happens for an empty list.
void framePoints(Camera& camera, const std::vector<glm::dvec3>& points, double aspect);

// framePoints with every vertex of the scene in world space (what the camera can see of it).
void frameScene(Camera& camera, const Scene& scene, double aspect);

// The right-handed basis glm::lookAt builds for a viewing direction (the up vector is +y, or -z looking straight up
// or down): right, up, forward (unit vectors).
struct ViewBasis {
    glm::dvec3 right, up, forward;
};
ViewBasis viewBasis(const glm::dvec3& forward);

// Sets near/far so the whole of `bounds` lies between them from the camera's position, with the near plane as far
// out as that allows (depth precision follows the scene's size).
void fitDepthRange(Camera& camera, const Bounds& bounds);

}  // namespace shadowlab
