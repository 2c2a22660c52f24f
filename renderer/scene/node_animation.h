#pragma once
// What a file's animations are made of, as the scene keeps them (glTF 2.0 §3.11): a node's local transform, and
// channels that drive one of its translation, rotation or scale through keyframes. Only data here; sampling and
// posing live in scene_animation.h, reading them from glTF in gltf_animation.h.
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/quaternion_double.hpp>
#include <glm/ext/vector_double3.hpp>

#include <string>
#include <vector>

namespace shadowlab {

// A node's local transform as the file gives it: a matrix (which no animation may target), or translation, rotation
// and scale, composed T * R * S.
struct NodeTransform {
    bool hasMatrix = false;
    glm::dmat4 matrix{1.0};
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // unit
    glm::dvec3 scale{1.0};
};

enum class AnimationPath { Translation, Rotation, Scale };
enum class Interpolation { Linear, Step, CubicSpline };

// One channel, checked when it was read: times finite and strictly increasing, values finite, counts matching.
struct AnimationChannel {
    int node = -1;  // the file's node index (Scene nodes that node placed carry it as SceneNode::gltfIndex)
    AnimationPath path = AnimationPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;   // seconds, at least one
    // Per key `components` floats (3, rotation 4 as x, y, z, w); cubic spline: in-tangent, value, out-tangent per key.
    std::vector<float> values;
    int components() const { return path == AnimationPath::Rotation ? 4 : 3; }
};

struct Animation {
    std::string name;   // the file's name, else "animation N"
    int index = 0;      // in the file's `animations` list
    std::vector<AnimationChannel> channels;
    double start = 0.0, end = 0.0;  // the first and last key over its channels (seconds)
};

}  // namespace shadowlab
