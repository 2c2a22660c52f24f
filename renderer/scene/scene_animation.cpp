#include "scene/scene_animation.h"

#include "scene/gltf_geometry.h"  // gltf::fitsFloat

#include <glm/ext/quaternion_common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>

namespace shadowlab {
namespace {

// Key `key`'s element `part` (cubic spline: 0 in-tangent, 1 value, 2 out-tangent; otherwise the value).
glm::dvec4 keyElement(const AnimationChannel& c, std::size_t key, int part) {
    const std::size_t n = std::size_t(c.components());
    const bool cubic = c.interpolation == Interpolation::CubicSpline;
    const float* p = c.values.data() + key * n * (cubic ? 3 : 1) + (cubic ? std::size_t(part) * n : 0);
    glm::dvec4 v(0.0);
    for (std::size_t i = 0; i < n; ++i) v[int(i)] = double(p[i]);
    return v;
}

glm::dquat quatOf(const glm::dvec4& xyzw) { return glm::dquat(xyzw.w, xyzw.x, xyzw.y, xyzw.z); }
glm::dvec4 xyzwOf(const glm::dquat& q) { return {q.x, q.y, q.z, q.w}; }

// A unit quaternion, or `fallback` when `v` has no length (a cubic spline can pass through zero).
glm::dvec4 unitQuaternion(const glm::dvec4& v, const glm::dvec4& fallback) {
    const double length = glm::length(v);
    return length > 1e-12 ? v / length : glm::normalize(fallback);
}

// One channel's value replaces that part of a node's local transform (the others keep the file's).
void applyChannel(NodeTransform& t, const AnimationChannel& c, const glm::dvec4& v) {
    switch (c.path) {
        case AnimationPath::Translation: t.translation = glm::dvec3(v); break;
        case AnimationPath::Rotation: t.rotation = quatOf(v); break;
        case AnimationPath::Scale: t.scale = glm::dvec3(v); break;
    }
}

// Scene nodes by the file's node index (a node two parents list was walked twice).
std::vector<std::vector<int>> nodesByGltfIndex(const Scene& scene) {
    int largest = -1;
    for (const SceneNode& n : scene.nodes) largest = std::max(largest, n.gltfIndex);
    std::vector<std::vector<int>> out(std::size_t(largest + 1));
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].gltfIndex >= 0) out[std::size_t(scene.nodes[i].gltfIndex)].push_back(int(i));
    return out;
}

// Every scene node's world transform with the chosen animations at `time`.
std::vector<glm::dmat4> worldTransforms(const Scene& scene, const std::vector<std::vector<int>>& byGltf,
                                        const std::vector<int>& chosen, double time) {
    std::vector<NodeTransform> local(scene.nodes.size());
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) local[i] = scene.nodes[i].local;
    for (int a : chosen)
        for (const AnimationChannel& c : scene.animations[std::size_t(a)].channels) {
            if (c.node < 0 || std::size_t(c.node) >= byGltf.size()) continue;  // a node the scene does not place
            const glm::dvec4 v = sampleChannel(c, time);
            for (int n : byGltf[std::size_t(c.node)]) applyChannel(local[std::size_t(n)], c, v);
        }
    std::vector<glm::dmat4> world(scene.nodes.size());
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const int parent = scene.nodes[i].parent;
        world[i] = parent < 0 ? localMatrix(local[i]) : world[std::size_t(parent)] * localMatrix(local[i]);
    }
    return world;
}

std::string animationList(const Scene& scene) {
    if (scene.animations.empty()) return "it has none";
    std::string list = "it has ";
    for (std::size_t i = 0; i < scene.animations.size() && i < 20; ++i)
        list += (i ? ", " : "") + std::to_string(i) + " \"" + scene.animations[i].name + "\"";
    if (scene.animations.size() > 20) list += ", ... (" + std::to_string(scene.animations.size()) + ")";
    return list + "; or all, none";
}

}  // namespace

glm::dmat4 localMatrix(const NodeTransform& t) {
    if (t.hasMatrix) return t.matrix;
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), t.translation);
    m *= glm::mat4_cast(t.rotation);
    return glm::scale(m, t.scale);
}

glm::dvec4 sampleChannel(const AnimationChannel& c, double time) {
    const std::vector<float>& keys = c.times;
    const std::size_t last = keys.size() - 1;
    const bool rotation = c.path == AnimationPath::Rotation;
    if (!(time > double(keys.front()))) return keyElement(c, 0, 1);  // before the first key (and NaN): it holds
    if (time >= double(keys[last])) return keyElement(c, last, 1);
    const std::size_t k = std::size_t(std::upper_bound(keys.begin(), keys.end(), time,
                                                       [](double t, float key) { return t < double(key); }) -
                                      keys.begin()) - 1;  // keys[k] <= time < keys[k + 1]
    const double t0 = keys[k], t1 = keys[k + 1], delta = t1 - t0, s = (time - t0) / delta;
    const glm::dvec4 v0 = keyElement(c, k, 1), v1 = keyElement(c, k + 1, 1);
    switch (c.interpolation) {
        case Interpolation::Step: return v0;
        case Interpolation::Linear:
            // glm::slerp takes the short way (it flips the second quaternion when their dot is negative).
            if (rotation) return xyzwOf(glm::slerp(glm::normalize(quatOf(v0)), glm::normalize(quatOf(v1)), s));
            return v0 + (v1 - v0) * s;
        case Interpolation::CubicSpline: {
            // glTF 2.0 Appendix C: p(s) = (2s³-3s²+1)v0 + (s³-2s²+s)·Δt·b0 + (-2s³+3s²)v1 + (s³-s²)·Δt·a1.
            const glm::dvec4 out0 = keyElement(c, k, 2) * delta, in1 = keyElement(c, k + 1, 0) * delta;
            const double s2 = s * s, s3 = s2 * s;
            const glm::dvec4 p = (2 * s3 - 3 * s2 + 1) * v0 + (s3 - 2 * s2 + s) * out0 + (-2 * s3 + 3 * s2) * v1 +
                                 (s3 - s2) * in1;
            return rotation ? unitQuaternion(p, v0) : p;
        }
    }
    return v0;
}

std::optional<std::vector<int>> chosenAnimations(const Scene& scene, const std::string& play, std::string& error) {
    std::vector<int> chosen;
    for (std::size_t i = 0; i < scene.animations.size(); ++i)
        if (scene.animations[i].name == play) return std::vector<int>{int(i)};
    if (play == "all") {
        for (std::size_t i = 0; i < scene.animations.size(); ++i) chosen.push_back(int(i));
        return chosen;
    }
    if (play == "none") return chosen;
    std::size_t index = 0;
    const auto [end, ec] = std::from_chars(play.data(), play.data() + play.size(), index);
    if (ec == std::errc{} && end == play.data() + play.size() && !play.empty() && index < scene.animations.size())
        return std::vector<int>{int(index)};
    error = "animation.play \"" + play + "\": the scene " + scene.name +
            " has no animation of that name or index (" + animationList(scene) + ")";
    return std::nullopt;
}

AnimationSpan animationSpan(const Scene& scene, const std::vector<int>& chosen) {
    AnimationSpan span;
    for (std::size_t i = 0; i < chosen.size(); ++i) {
        const Animation& a = scene.animations[std::size_t(chosen[i])];
        span.start = i == 0 ? a.start : std::min(span.start, a.start);
        span.end = i == 0 ? a.end : std::max(span.end, a.end);
    }
    return span;
}

void poseScene(Scene& scene, const std::vector<int>& chosen, double time) {
    if (scene.animations.empty()) return;  // nothing moves: the loader's transforms stand
    const std::vector<glm::dmat4> world = worldTransforms(scene, nodesByGltfIndex(scene), chosen, time);
    for (Instance& instance : scene.instances) {
        if (instance.node < 0) continue;  // placed by no recorded node: it stays
        const glm::dmat4& m = world[std::size_t(instance.node)];
        instance.transform = gltf::fitsFloat(m) ? glm::mat4(m) : glm::mat4(0.0f);
    }
    // Lights and cameras follow their node's pose; one the pose cannot place (no -Z, beyond a float) stays put.
    for (SceneLight& light : scene.lights) {
        if (light.node < 0 || !gltf::fitsFloat(world[std::size_t(light.node)])) continue;
        const NodeFrame frame = nodeFrame(world[std::size_t(light.node)]);
        if (!frame.forward) continue;
        light.position = glm::vec3(frame.position);
        light.direction = glm::vec3(*frame.forward);
    }
    for (SceneCamera& camera : scene.cameras) {
        if (camera.node < 0 || !gltf::fitsFloat(world[std::size_t(camera.node)])) continue;
        const NodeFrame frame = nodeFrame(world[std::size_t(camera.node)]);
        if (!frame.forward) continue;
        camera.position = frame.position;
        camera.forward = *frame.forward;
    }
}

std::string poseScene(Scene& scene, const AnimationSettings& animation) {
    std::string error;
    const std::optional<std::vector<int>> chosen = chosenAnimations(scene, animation.play, error);
    if (!chosen) return error;
    poseScene(scene, *chosen, double(animation.time));
    return {};
}

std::string animationNote(const Scene& scene, const AnimationSettings& animation) {
    auto seconds = [](double v) {
        char text[32];
        std::snprintf(text, sizeof text, "%g s", v);
        return std::string(text);
    };
    std::string note = "scene " + scene.name + ": " + std::to_string(scene.animations.size()) + " animation" +
                       (scene.animations.size() == 1 ? "" : "s") + " (";
    for (std::size_t i = 0; i < scene.animations.size() && i < 20; ++i) {
        const Animation& a = scene.animations[i];
        note += (i ? ", " : "") + std::to_string(i) + " \"" + a.name + "\" " + seconds(a.start) + " to " + seconds(a.end);
    }
    if (scene.animations.size() > 20) note += ", ...";
    return note + "); playing " + animation.play + " at " + seconds(double(animation.time));
}

void extendBoundsOverAnimations(Scene& scene) {
    if (scene.animations.empty() || scene.nodes.empty()) return;
    const std::vector<std::vector<int>> byGltf = nodesByGltfIndex(scene);
    // Which nodes move (a channel drives them or an ancestor) and the instances they carry.
    std::vector<char> moves(scene.nodes.size(), 0);
    std::size_t channels = 0;
    for (const Animation& a : scene.animations)
        for (const AnimationChannel& c : a.channels) {
            ++channels;
            if (c.node >= 0 && std::size_t(c.node) < byGltf.size())
                for (int n : byGltf[std::size_t(c.node)]) moves[std::size_t(n)] = 1;
        }
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].parent >= 0 && moves[std::size_t(scene.nodes[i].parent)]) moves[i] = 1;
    std::vector<std::size_t> moving;
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
        if (scene.instances[i].node >= 0 && moves[std::size_t(scene.instances[i].node)]) moving.push_back(i);
    if (moving.empty()) return;
    // Each mesh's box in its own space; posed, its bounding sphere stands for it, so a rotation between two sampled
    // times stays inside (a bound a little loose for what moves, not short).
    std::vector<Bounds> meshBox(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        for (const glm::vec3& p : scene.meshes[m].positions) meshBox[m].extend(p);

    // Poses are bounded: about 2e7 node, channel and instance evaluations in all, whatever the file holds.
    const std::size_t perPose = scene.nodes.size() + channels + 8 * moving.size();
    const std::size_t poseBudget = std::clamp<std::size_t>(std::size_t(2e7) / std::max<std::size_t>(perPose, 1), 8, 4096);
    auto extendAt = [&](const std::vector<int>& chosen, double time) {
        const std::vector<glm::dmat4> world = worldTransforms(scene, byGltf, chosen, time);
        for (std::size_t i : moving) {
            const Instance& inst = scene.instances[i];
            const Bounds& box = meshBox[std::size_t(inst.mesh)];
            const glm::dmat4& m = world[std::size_t(inst.node)];
            if (box.empty || !gltf::fitsFloat(m)) continue;
            const double stretch = std::max({glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])),
                                             glm::length(glm::dvec3(m[2]))});
            const glm::dvec3 centre(m * glm::dvec4(glm::dvec3(box.center()), 1.0));
            const double radius = stretch * double(box.radius());
            scene.bounds.extend(glm::vec3(centre - radius));
            scene.bounds.extend(glm::vec3(centre + radius));
        }
    };
    // Sample times: every key of the set and seven points between consecutive keys, thinned to the budget.
    auto sampleTimes = [&](const std::vector<int>& chosen, std::size_t budget) {
        std::size_t keyCount = 0;
        for (int a : chosen)
            for (const AnimationChannel& c : scene.animations[std::size_t(a)].channels) keyCount += c.times.size();
        std::vector<double> keys;
        if (keyCount > 8 * budget) {  // far more keys than poses: evenly over the span (no sort of millions)
            const AnimationSpan span = animationSpan(scene, chosen);
            for (std::size_t i = 0; i < budget; ++i)
                keys.push_back(span.start + (span.end - span.start) * double(i) / double(budget - 1));
            return keys;
        }
        for (int a : chosen)
            for (const AnimationChannel& c : scene.animations[std::size_t(a)].channels)
                keys.insert(keys.end(), c.times.begin(), c.times.end());
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
        std::vector<double> times;
        for (std::size_t k = 0; k < keys.size(); ++k) {
            times.push_back(keys[k]);
            if (k + 1 < keys.size())
                for (int q = 1; q < 8; ++q) times.push_back(keys[k] + (keys[k + 1] - keys[k]) * q / 8.0);
        }
        if (times.size() <= budget) return times;
        std::vector<double> thinned;
        for (std::size_t i = 0; i < budget; ++i) thinned.push_back(times[i * (times.size() - 1) / (budget - 1)]);
        return thinned;
    };
    std::vector<int> all;
    for (std::size_t a = 0; a < scene.animations.size(); ++a) all.push_back(int(a));
    const std::size_t share = std::max<std::size_t>(poseBudget / (scene.animations.size() + 1), 2);
    for (double t : sampleTimes(all, std::max(share, poseBudget / 2))) extendAt(all, t);
    if (scene.animations.size() > 1 && scene.animations.size() * 2 <= poseBudget)
        for (int a : all)
            for (double t : sampleTimes({a}, share)) extendAt({a}, t);
}

}  // namespace shadowlab
