#include "accuracy/motion.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace shadowlab {

namespace {

bool finiteVec(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Rodrigues: v rotated by `radians` about the unit `axis`.
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

// A user's direction as a unit vector: scaled by its largest component first, so 1e300,0,0 (whose length overflows
// to infinity, and glm::normalize to zero) and 1e-300,0,0 (whose length underflows) are both the unit X axis.
// Zero for a zero or non-finite vector.
glm::dvec3 unitDirection(const glm::dvec3& v) {
    if (!finiteVec(v)) return glm::dvec3(0.0);
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(largest > 0.0)) return glm::dvec3(0.0);
    return glm::normalize(v / largest);
}

glm::dvec3 sceneCentre(const Bounds& bounds) {
    return bounds.centreOrOrigin();
}

// What a light motion turns: a point light's offset from the scene's centre, else its direction.
glm::dvec3 rotated(const LightSettings& light, const Bounds& bounds) {
    return light.type == LightType::Point ? glm::dvec3(light.position) - sceneCentre(bounds)
                                          : glm::dvec3(light.direction);
}

}  // namespace

const std::vector<MotionInfo>& motionKinds() {
    static const std::vector<MotionInfo> kinds = {
        {MotionKind::Camera, "camera", "world units", 0.002},
        {MotionKind::CameraTurn, "camera-turn", "degrees", 0.1},
        {MotionKind::Light, "light", "degrees", 0.02},
        {MotionKind::Animation, "animation", "seconds", 1.0 / 30.0},
    };
    return kinds;
}

const MotionInfo& motionInfo(MotionKind kind) {
    for (const MotionInfo& info : motionKinds())
        if (info.kind == kind) return info;
    return motionKinds().front();
}

std::optional<MotionKind> parseMotion(const std::string& name) {
    for (const MotionInfo& info : motionKinds())
        if (name == info.name) return info.kind;
    return std::nullopt;
}

std::string motionNames() {
    std::string text;
    const std::vector<MotionInfo>& kinds = motionKinds();
    for (std::size_t i = 0; i < kinds.size(); ++i)
        text += std::string(i == 0 ? "" : i + 1 == kinds.size() ? " or " : ", ") + kinds[i].name;
    return text;
}

std::string motionError(const Motion& motion, const Bounds& sceneBounds) {
    std::ostringstream out;
    if (motion.frames < 2 || motion.frames > kMaxMotionFrames) {
        out << "--frames " << motion.frames << ": flicker compares consecutive frames, so it needs 2.."
            << kMaxMotionFrames << " frames";
        return out.str();
    }
    if (!std::isfinite(motion.step)) return "--step: must be a finite number";
    if (motion.kind == MotionKind::Animation) {
        if (motion.step > 0.0 && motion.step <= kMaxAnimationStepSeconds) return "";
        out << "--step " << motion.step << ": an animation step is in seconds per frame, in (0, "
            << kMaxAnimationStepSeconds << "]";
        return out.str();
    }
    if (motion.kind != MotionKind::Camera && std::abs(motion.step) > kMaxTurnStepDeg) {
        out << "--step " << motion.step << ": a " << motionName(motion.kind)
            << " step is in degrees per frame, at most " << kMaxTurnStepDeg << " (flicker is about sub-texel steps)";
        return out.str();
    }
    const double diameter = sceneBounds.empty ? 2.0 : 2.0 * double(sceneBounds.radius());
    if (motion.kind == MotionKind::Camera && std::abs(motion.step) > kMaxCameraStepDiameters * diameter) {
        out << "--step " << motion.step << ": a camera step is in world units per frame, at most the scene's diameter ("
            << diameter << ") (flicker is about sub-texel steps)";
        return out.str();
    }
    if (motion.direction && unitDirection(*motion.direction) == glm::dvec3(0.0))
        return motion.kind == MotionKind::Camera ? "--direction: the camera's direction of travel must be finite and non-zero"
                                                 : "--direction: the rotation axis must be finite and non-zero";
    return "";
}

Camera cameraAtFrame(const Camera& start, const Motion& motion, int frame) {
    if (motion.kind == MotionKind::CameraTurn) {
        const glm::dvec3 axis = motion.direction ? unitDirection(*motion.direction) : glm::dvec3(0.0, 1.0, 0.0);
        Camera camera = start;
        camera.target = start.position +
                        rotate(start.target - start.position, axis, glm::radians(motion.step * double(frame)));
        return camera;
    }
    if (motion.kind != MotionKind::Camera) return start;
    const glm::dvec3 along = motion.direction ? unitDirection(*motion.direction)
                                              : viewBasis(start.target - start.position).right;
    const glm::dvec3 offset = along * (motion.step * double(frame));
    Camera camera = start;
    camera.position += offset;
    camera.target += offset;
    return camera;
}

double animationTimeAtFrame(double start, const Motion& motion, int frame) {
    return motion.kind == MotionKind::Animation ? start + motion.step * double(frame) : start;
}

glm::dvec3 lightRotationAxis(const LightSettings& light, const Motion& motion, const Bounds& sceneBounds) {
    if (motion.direction) return unitDirection(*motion.direction);
    const glm::dvec3 v = rotated(light, sceneBounds);
    const glm::dvec3 across = glm::cross(v, glm::dvec3(0.0, 1.0, 0.0));
    const double length = glm::length(across);
    // Parallel to world up (or a point light at the centre): world X, as the header says.
    return length > 1e-9 * std::max(glm::length(v), 1e-300) ? across / length : glm::dvec3(1.0, 0.0, 0.0);
}

LightSettings lightAtFrame(const LightSettings& start, const Motion& motion, const Bounds& sceneBounds, int frame) {
    if (motion.kind != MotionKind::Light) return start;
    const double angle = glm::radians(motion.step * double(frame));
    const glm::dvec3 turned = rotate(rotated(start, sceneBounds), lightRotationAxis(start, motion, sceneBounds), angle);
    LightSettings light = start;
    if (start.type == LightType::Point)
        light.position = glm::vec3(sceneCentre(sceneBounds) + turned);
    else
        light.direction = glm::vec3(turned);
    return light;
}

}  // namespace shadowlab
