#pragma once
// The scene at time t: the chosen animations' channels sampled (glTF 2.0 interpolation: STEP holds, LINEAR lerps,
// rotations slerp on the shortest path, CUBICSPLINE is the Hermite spline with tangents scaled by the key interval),
// the node hierarchy's world transforms re-evaluated and every instance placed by a node moved with it. Times
// outside an animation's keys clamp to its first or last key. No GL.
#include "scene/scene.h"
#include "settings/settings.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double4.hpp>

#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

// T * R * S, or the node's matrix.
glm::dmat4 localMatrix(const NodeTransform& transform);

// The channel's value at `time` (clamped to its keys): x, y, z (translation, scale) or a unit quaternion x, y, z, w.
glm::dvec4 sampleChannel(const AnimationChannel& channel, double time);

// The animations animation.play names in `scene`: "all", "none", an animation's name (an exact match first) or its
// index. nullopt with `error` naming the key, the value and the scene's animations when there is no such one.
std::optional<std::vector<int>> chosenAnimations(const Scene& scene, const std::string& play, std::string& error);

// The time span the chosen animations cover: [earliest first key, latest last key]; {0, 0} for none.
struct AnimationSpan {
    double start = 0.0, end = 0.0;
};
AnimationSpan animationSpan(const Scene& scene, const std::vector<int>& chosen);

// Moves the scene's instances to the pose of the chosen animations at `time` (nodes no channel drives keep the
// file's transform). A pose whose world transform does not fit a float collapses that instance to a point.
void poseScene(Scene& scene, const std::vector<int>& chosen, double time);

// The same from the settings' animation.play and animation.time; "" or the error of chosenAnimations.
std::string poseScene(Scene& scene, const AnimationSettings& animation);

// One line for users: the scene's animations (index, name, key span) and what plays at which time.
std::string animationNote(const Scene& scene, const AnimationSettings& animation);

// Extends scene.bounds over the poses the animations reach (each alone and all together, sampled at their keys and
// seven times between them; each moving mesh as its bounding sphere, which holds it in any rotation), leaving the
// instances where they were. Bounded work however many keys and nodes a file has.
void extendBoundsOverAnimations(Scene& scene);

}  // namespace shadowlab
