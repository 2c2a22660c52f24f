#include "frame/camera.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

ViewBasis viewBasis(const glm::dvec3& direction) {
    glm::dvec3 forward = glm::length(direction) < 1e-12 ? glm::dvec3(0.0, 0.0, -1.0) : glm::normalize(direction);
    // Looking straight up or down: up=(0,1,0) would be parallel, so use -z as up there.
    const glm::dvec3 worldUp = std::abs(forward.y) > 0.999 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, worldUp));
    return {right, glm::cross(right, forward), forward};
}

glm::dmat4 Camera::view(const glm::dvec3& origin) const {
    const ViewBasis basis = viewBasis(target - position);
    // Built relative to the render origin in double: the eye may be 1e6 from the world's origin.
    return glm::lookAt(position - origin, position - origin + basis.forward, basis.up);
}

glm::dmat4 Camera::projection(double aspect) const {
    aspect = std::max(aspect, 1e-6);
    if (orthoHalfHeight > 0.0) {
        const double halfWidth = orthoHalfHeight * aspect;
        return glm::ortho(-halfWidth, halfWidth, -orthoHalfHeight, orthoHalfHeight, nearPlane, farPlane);
    }
    return glm::perspective(glm::radians(fovYDeg), aspect, nearPlane, farPlane);
}

double Camera::worldPerPixel(double depth, int heightPixels) const {
    const double height = double(std::max(heightPixels, 1));
    if (orthoHalfHeight > 0.0) return 2.0 * orthoHalfHeight / height;
    return depth * 2.0 * std::tan(glm::radians(fovYDeg) / 2.0) / height;
}

ViewCamera viewCameraOf(const Camera& camera, double aspect, const glm::dvec3& origin) {
    const ViewBasis basis = viewBasis(camera.target - camera.position);
    ViewCamera v;
    v.eye = camera.position - origin;
    v.forward = basis.forward;
    v.right = basis.right;
    v.up = basis.up;
    v.tanHalfFovY = std::tan(glm::radians(camera.fovYDeg) * 0.5);
    v.aspect = std::max(aspect, 1e-6);
    v.nearPlane = camera.nearPlane;
    v.farPlane = camera.farPlane;
    return v;
}

void framePoints(Camera& camera, const std::vector<glm::dvec3>& points, double aspect) {
    if (points.empty()) return;
    const ViewBasis b = viewBasis(camera.target - camera.position);
    // Half-extents of the view (tangents), shrunk so the subject fills kAutoFrameFill of the limiting dimension.
    const double ty = std::tan(glm::radians(camera.fovYDeg) * 0.5) * kAutoFrameFill;
    const double tx = ty * std::max(aspect, 1e-6);
    // In the eye's frame a point is inside when |x| <= tx z and |y| <= ty z, with x = P - eyeX, z = Q - eyeZ (P, Q,
    // eyeX, eyeZ: world coordinates along right / forward). Each side gives a bound linear in the eye's position;
    // the tightest per side are these maxima.
    const double lowest = -std::numeric_limits<double>::max();
    double rightMax = lowest, leftMax = lowest, topMax = lowest, bottomMax = lowest, depthSum = 0.0;
    for (const glm::dvec3& p : points) {
        const double x = glm::dot(p, b.right), y = glm::dot(p, b.up), z = glm::dot(p, b.forward);
        rightMax = std::max(rightMax, x - tx * z);
        leftMax = std::max(leftMax, -x - tx * z);
        topMax = std::max(topMax, y - ty * z);
        bottomMax = std::max(bottomMax, -y - ty * z);
        depthSum += z;
    }
    // Touching both sides: eyeX - tx eyeZ = rightMax and -eyeX - tx eyeZ = leftMax, so eyeZ = -(r + l) / (2 tx).
    // The dimension that needs the eye further back limits; the other is centred with slack on both sides.
    double eyeZ = std::min(-(rightMax + leftMax) / (2.0 * tx), -(topMax + bottomMax) / (2.0 * ty));
    const double eyeX = 0.5 * (rightMax - leftMax), eyeY = 0.5 * (topMax - bottomMax);
    const double meanZ = depthSum / double(points.size());
    // A subject with no extent (one point) would put the eye on it: keep a little distance.
    const double minDistance = 1e-3 * std::max(1.0, std::abs(meanZ) * 1e-9);
    eyeZ = std::min(eyeZ, meanZ - minDistance);
    camera.position = b.right * eyeX + b.up * eyeY + b.forward * eyeZ;
    const double meanDepth = meanZ - eyeZ;
    camera.target = camera.position + b.forward * std::max(meanDepth, 1e-6);
}

namespace {

// Every vertex of every instance in world space: the hull the auto-framed view must hold.
std::vector<glm::dvec3> worldVertices(const Scene& scene) {
    std::vector<glm::dvec3> points;
    for (const Instance& inst : scene.instances) {
        const Mesh& mesh = scene.meshes[std::size_t(inst.mesh)];
        const glm::dmat4 transform(inst.transform);
        for (const glm::vec3& p : mesh.positions) {
            const glm::dvec3 world(transform * glm::dvec4(glm::dvec3(p), 1.0));
            if (std::isfinite(world.x) && std::isfinite(world.y) && std::isfinite(world.z)) points.push_back(world);
        }
    }
    return points;
}

}  // namespace

void frameScene(Camera& camera, const Scene& scene, double aspect) {
    // An animated scene is framed by its bounds' corners, which hold every pose: the view holds still while it plays.
    if (!scene.animations.empty() && !scene.bounds.empty) {
        std::vector<glm::dvec3> corners;
        for (int c = 0; c < 8; ++c)
            corners.emplace_back((c & 1) ? scene.bounds.max.x : scene.bounds.min.x,
                                 (c & 2) ? scene.bounds.max.y : scene.bounds.min.y,
                                 (c & 4) ? scene.bounds.max.z : scene.bounds.min.z);
        return framePoints(camera, corners, aspect);
    }
    framePoints(camera, worldVertices(scene), aspect);
}

CameraSettings recordedCamera(const Camera& used, bool autoFrame) {
    CameraSettings out;
    out.autoFrame = autoFrame;
    out.position = used.position;
    out.target = used.target;
    out.fovYDeg = float(used.fovYDeg);
    return out;
}

std::string sceneCameraError(const CameraSettings& settings, const Scene& scene) {
    const int index = settings.sceneCamera;
    if (index == -1 || (index >= 0 && std::size_t(index) < scene.cameras.size())) return {};
    std::string error = "camera.sceneCamera: " + std::to_string(index) + " is not a camera of scene " + scene.name;
    if (scene.cameras.empty()) return error + " (it has none; allowed -1, the free camera)";
    error += " (allowed -1 = the free camera, or 0.." + std::to_string(scene.cameras.size() - 1) + ":";
    for (std::size_t i = 0; i < scene.cameras.size() && i < 8; ++i)
        error += (i ? ", " : " ") + std::to_string(i) + " '" + scene.cameras[i].name + "'";
    return error + (scene.cameras.size() > 8 ? ", ...)" : ")");
}

Camera sceneCameraView(const SceneCamera& file, const Bounds& bounds) {
    Camera camera;
    camera.position = file.position;
    // The target only gives the direction (and the orbit's pivot distance): the scene's centre's depth along it.
    const double depth = glm::dot(bounds.centreOrOrigin() - file.position, file.forward);
    camera.target = file.position + file.forward * std::max(depth, 1e-3 * std::max(1.0, double(bounds.radius())));
    if (file.orthographic)
        camera.orthoHalfHeight = file.ymag;
    else
        camera.fovYDeg = glm::degrees(file.yfovRad);
    fitDepthRange(camera, bounds);  // the far plane of an infinite projection: the scene's reach
    camera.nearPlane = file.znear;
    if (file.zfar > 0.0) camera.farPlane = file.zfar;
    camera.farPlane = std::max(camera.farPlane, camera.nearPlane * (1.0 + 1e-6) + 1e-6);
    return camera;
}

Camera cameraFor(const CameraSettings& settings, const Scene& scene, double aspect) {
    const Bounds& bounds = scene.bounds;
    if (settings.sceneCamera >= 0 && std::size_t(settings.sceneCamera) < scene.cameras.size())
        return sceneCameraView(scene.cameras[std::size_t(settings.sceneCamera)], bounds);
    Camera camera;
    camera.fovYDeg = settings.fovYDeg;
    if (settings.autoFrame && scene.viewpoint) {
        camera.position = scene.viewpoint->position;
        camera.target = scene.viewpoint->target;
    } else if (settings.autoFrame) {
        // A three-quarter view from above (by default across the default light, so shadows fall to the side, not
        // behind the objects), moved so the scene's vertices fill the frame.
        const glm::dvec3 center = bounds.centreOrOrigin();
        camera.target = center;
        camera.position = center + glm::normalize(glm::dvec3(scene.viewDirection));
        frameScene(camera, scene, aspect);
    } else {
        camera.position = settings.position;
        camera.target = settings.target;
    }
    fitDepthRange(camera, bounds);
    return camera;
}

void fitDepthRange(Camera& camera, const Bounds& bounds) {
    const glm::dvec3 center = bounds.centreOrOrigin();
    const double radius = bounds.empty ? 1.0 : std::max(double(bounds.radius()), 1e-3);
    const double reach = glm::length(camera.position - center) + radius;
    camera.farPlane = reach * 1.05;
    camera.nearPlane = std::max(camera.farPlane * 1e-4, 1e-4);
}

}  // namespace shadowlab
