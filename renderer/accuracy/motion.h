#pragma once
// The motions the flicker measure (flicker.h) plays back: the camera translated or turned, or a light rotated, by a
// fixed step per frame. Frame f is computed from frame 0 in double precision (f x step, not f additions), so a sub-texel step
// stays exactly that many steps away after hundreds of frames. No GL.
#include "frame/camera.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <glm/ext/vector_double3.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

enum class MotionKind {
    Camera,      // the camera (position and target) moves `step` world units per frame
    CameraTurn,  // the camera turns its view `step` degrees per frame about its position (default axis: world up)
    Light,       // the light rotates `step` degrees per frame (directional / spot: its direction; point: its position
                 // about the scene's centre)
    Animation,   // the scene's animations (animation.play) advance `step` seconds per frame from animation.time
};

// One source for every motion's name, step unit and a typical sub-texel step (CLI, JSON, editor).
struct MotionInfo {
    MotionKind kind;
    const char* name;   // "camera", "camera-turn", "light"
    const char* unit;   // "world units", "degrees"
    double typicalStep; // a sub-texel step on a 2048² map of a scene some 20 units across (the editor's default)
};
const std::vector<MotionInfo>& motionKinds();
const MotionInfo& motionInfo(MotionKind kind);
inline const char* motionName(MotionKind kind) { return motionInfo(kind).name; }
std::optional<MotionKind> parseMotion(const std::string& name);
std::string motionNames();  // "camera, camera-turn, light or animation"
inline bool movesCamera(MotionKind kind) { return kind == MotionKind::Camera || kind == MotionKind::CameraTurn; }

struct Motion {
    MotionKind kind = MotionKind::Camera;
    double step = 0.0;  // camera: world units per frame; light: degrees per frame
    int frames = 2;     // frames rendered (>= 2): frames - 1 consecutive pairs
    std::size_t light = 0;  // the measured light, an index into the effective lights (light/scene_lights.h)
    // Camera: the direction of travel (default: the camera's right vector). Camera turn: the axis through the camera's
    // position (default: world up). Light: the rotation axis (default:
    // perpendicular to the light's direction (point: its offset from the scene's centre) and world up; world X
    // when they are parallel). Normalized when used; must be finite and non-zero when given.
    std::optional<glm::dvec3> direction;
};

// The limits a motion must respect; anything beyond is a typo, not a flicker experiment.
inline constexpr int kMaxMotionFrames = 1000;
// Frames played when none are asked for (`measure --motion`, a check case's flicker limit).
inline constexpr int kDefaultMotionFrames = 10;
inline constexpr double kMaxTurnStepDeg = 45.0;  // per frame: a light's or the camera's turn
inline constexpr double kMaxAnimationStepSeconds = 60.0;  // per frame: beyond it nothing is compared frame to frame
// Camera: at most this many scene diameters per frame.
inline constexpr double kMaxCameraStepDiameters = 1.0;

// "" when the motion can be played on a scene of this size, else why, naming the option (`--frames`, `--step`,
// `--direction`) so both the CLI and the editor can show it as it is.
std::string motionError(const Motion& motion, const Bounds& sceneBounds);

// The camera of frame f (camera motions; the camera itself for a light motion).
Camera cameraAtFrame(const Camera& start, const Motion& motion, int frame);

// The light of frame f (light motion; the light itself for a camera motion). `sceneBounds`: the point light's centre
// of rotation.
LightSettings lightAtFrame(const LightSettings& start, const Motion& motion, const Bounds& sceneBounds, int frame);

// The animation time of frame f: `start` + f x step (animation motion; `start` for the others).
double animationTimeAtFrame(double start, const Motion& motion, int frame);

// The unit rotation axis a light motion uses for `light` (the given direction, or the default above).
glm::dvec3 lightRotationAxis(const LightSettings& light, const Motion& motion, const Bounds& sceneBounds);

}  // namespace shadowlab
