#include "scene/gltf_animation.h"

#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace shadowlab::gltf {
namespace {

// A value beyond this moves or scales a node past what a float scene can hold (the loader's extent limit).
constexpr double kMaxAnimatedValue = 1e18;

const char* pathName(AnimationPath path) {
    switch (path) {
        case AnimationPath::Translation: return "translation";
        case AnimationPath::Rotation: return "rotation";
        case AnimationPath::Scale: return "scale";
    }
    return "?";
}

std::optional<AnimationPath> parsePath(const std::string& path) {
    if (path == "translation") return AnimationPath::Translation;
    if (path == "rotation") return AnimationPath::Rotation;
    if (path == "scale") return AnimationPath::Scale;
    return std::nullopt;
}

std::optional<Interpolation> parseInterpolation(const std::string& text) {
    if (text.empty() || text == "LINEAR") return Interpolation::Linear;
    if (text == "STEP") return Interpolation::Step;
    if (text == "CUBICSPLINE") return Interpolation::CubicSpline;
    return std::nullopt;
}

// Counts an accessor's floats against the budget before they are read ("" or why not).
std::string takeBudget(const tg::Model& m, int accessor, std::size_t components, DecodeBudget& budget) {
    if (accessor < 0 || accessor >= int(m.accessors.size())) return {};  // readFloats names the missing accessor
    const std::size_t count = m.accessors[std::size_t(accessor)].count;
    if (count > kMaxDecodedBytes / (components * sizeof(float)) || !budget.take(count * components * sizeof(float)))
        return "accessor " + str(accessor) + " (" + str(count) + " keys) passes the scene's " +
               str(kMaxDecodedBytes >> 20) + " MiB decode limit";
    return {};
}

// Reads and checks one channel; "" and `out` filled, or why it cannot be played.
std::string readChannel(const tg::Model& m, const tg::Animation& a, const tg::AnimationChannel& c,
                        AnimationPath path, DecodeBudget& budget, AnimationChannel& out) {
    if (c.target_node < 0 || c.target_node >= int(m.nodes.size()))
        return "it targets node " + str(c.target_node) + ", which does not exist (the file has " +
               str(m.nodes.size()) + " nodes)";
    if (m.nodes[std::size_t(c.target_node)].matrix.size() == 16)
        return "it targets node " + str(c.target_node) +
               ", which has a matrix (glTF: an animated node has translation, rotation and scale only)";
    if (c.sampler < 0 || c.sampler >= int(a.samplers.size()))
        return "sampler " + str(c.sampler) + " does not exist (the animation has " + str(a.samplers.size()) + ")";
    const tg::AnimationSampler& s = a.samplers[std::size_t(c.sampler)];
    const std::string sampler = "sampler " + str(c.sampler);
    const std::optional<Interpolation> interpolation = parseInterpolation(s.interpolation);
    if (!interpolation)
        return sampler + ": unknown interpolation \"" + s.interpolation + "\" (LINEAR, STEP or CUBICSPLINE)";
    out.node = c.target_node;
    out.path = path;
    out.interpolation = *interpolation;
    const std::size_t comps = std::size_t(out.components());
    for (const auto& [accessor, n] : {std::pair{s.input, std::size_t(1)}, std::pair{s.output, comps}})
        if (std::string why = takeBudget(m, accessor, n, budget); !why.empty()) return sampler + ": " + why;
    std::string err;
    if (!readFloats(m, s.input, TINYGLTF_TYPE_SCALAR, out.times, err)) return sampler + "'s input: " + err;
    if (!readFloats(m, s.output, comps == 4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, out.values, err))
        return sampler + "'s output: " + err;
    const std::string input = sampler + "'s input (accessor " + str(s.input) + ")";
    if (out.times.empty()) return input + " has no keys";
    for (std::size_t k = 0; k < out.times.size(); ++k) {
        if (!std::isfinite(out.times[k])) return input + ": key " + str(k) + " is not a finite time";
        if (k > 0 && !(out.times[k] > out.times[k - 1]))
            return input + " is not strictly increasing: key " + str(k) + " at " + str(double(out.times[k])) +
                   " s follows " + str(double(out.times[k - 1])) + " s";
    }
    const bool cubic = out.interpolation == Interpolation::CubicSpline;
    const std::size_t perKey = comps * (cubic ? 3 : 1);
    const std::string output = sampler + "'s output (accessor " + str(s.output) + ")";
    if (out.values.size() != out.times.size() * perKey)
        return output + " holds " + str(out.values.size() / comps) + " elements for " + str(out.times.size()) +
               " keys (" + (cubic ? "CUBICSPLINE needs 3 a key: in-tangent, value, out-tangent" : "one a key") + ")";
    for (std::size_t i = 0; i < out.values.size(); ++i)
        if (!(std::abs(double(out.values[i])) <= kMaxAnimatedValue))
            return output + ": key " + str(i / perKey) + " holds " + str(double(out.values[i])) +
                   " (not a finite number within 1e18)";
    if (path == AnimationPath::Rotation)
        for (std::size_t k = 0; k < out.times.size(); ++k) {
            const float* q = out.values.data() + k * perKey + (cubic ? comps : 0);
            if (!(std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2] + double(q[3]) * q[3]) >
                  1e-12))
                return output + ": key " + str(k) + " is a zero quaternion (no rotation)";
        }
    return {};
}

}  // namespace

std::vector<Animation> importAnimations(const tg::Model& m, DecodeBudget& budget, const Warn& warn) {
    std::vector<Animation> animations;
    std::size_t weightChannels = 0;
    for (std::size_t i = 0; i < m.animations.size() && !budget.exceeded; ++i) {
        const tg::Animation& a = m.animations[i];
        Animation animation;
        animation.index = int(i);
        animation.name = a.name.empty() ? "animation " + str(i) : a.name;
        const std::string label = "animation " + str(i) + (a.name.empty() ? "" : " \"" + a.name + "\"");
        std::string refused;
        for (std::size_t c = 0; c < a.channels.size() && refused.empty(); ++c) {
            const tg::AnimationChannel& channel = a.channels[c];
            const std::optional<AnimationPath> path = parsePath(channel.target_path);
            if (!path && channel.target_path == "weights") {
                ++weightChannels;
                continue;
            }
            const std::string where = "channel " + str(c) + " (node " + str(channel.target_node) + " " +
                                      (path ? pathName(*path) : "\"" + channel.target_path + "\"") + ")";
            if (!path) {
                refused = where + ": unknown target path (translation, rotation, scale or weights)";
                break;
            }
            AnimationChannel read;
            if (std::string why = readChannel(m, a, channel, *path, budget, read); !why.empty()) {
                refused = where + ": " + why;
                break;
            }
            animation.channels.push_back(std::move(read));
        }
        if (budget.exceeded) break;  // the loader refuses the file, naming the limit
        if (!refused.empty()) {
            warn(label + ", " + refused + "; the animation is skipped");
            continue;
        }
        if (animation.channels.empty()) continue;  // nothing it moves is played (weights only, or no channels)
        animation.start = animation.channels.front().times.front();
        animation.end = animation.channels.front().times.back();
        for (const AnimationChannel& c : animation.channels) {
            animation.start = std::min(animation.start, double(c.times.front()));
            animation.end = std::max(animation.end, double(c.times.back()));
        }
        animations.push_back(std::move(animation));
    }
    if (weightChannels > 0)
        warn(str(weightChannels) + " morph-target weight channel" + (weightChannels == 1 ? " is" : "s are") +
             " not played: meshes keep their base shape");
    return animations;
}

std::vector<char> animatedNodes(const tg::Model& m, const std::vector<Animation>& animations) {
    std::vector<char> animated(m.nodes.size(), 0);
    for (const Animation& a : animations)
        for (const AnimationChannel& c : a.channels) animated[std::size_t(c.node)] = 1;
    return animated;
}

}  // namespace shadowlab::gltf
