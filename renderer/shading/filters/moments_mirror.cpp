#include "shading/filters/moments_mirror.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

glm::vec4 storedMoments(const glm::vec4& value, const MomentTechnique& technique, int momentBits) {
    glm::vec4 out = value;
    for (int c = 0; c < 4; ++c) {
        if (c >= technique.channels) out[c] = 0.0f;  // RG storage reads back 0 in the missing channels
        else if (momentBits == 32) continue;
        else if (technique.unorm16) out[c] = std::round(std::clamp(value[c], 0.0f, 1.0f) * 65535.0f) / 65535.0f;
        else out[c] = glm::unpackHalf1x16(glm::packHalf1x16(value[c]));
    }
    return out;
}

float momentDepth(float window, const MomentDepthConvention& c) {
    if (!c.perspective) return c.reversedZ ? 1.0f - window : window;
    const float n = c.nearPlane, f = c.farPlane;
    const float distance = c.reversedZ ? n * f / (n + window * (f - n))
                                       : 2.0f * f * n / ((f + n) - (2.0f * window - 1.0f) * (f - n));
    return (distance - n) / (f - n);
}

std::vector<glm::vec4> momentsOfDepth(const std::vector<float>& depth, int resolution,
                                      const MomentDepthConvention& convention, const FilterSettings& filter,
                                      double blurWidthTexels) {
    const MomentTechnique& technique = *filterTechnique(filter.kind).moments;
    const glm::vec4 uniforms = technique.uniforms(filter);
    const int bits = filter.momentBits;
    std::vector<glm::vec4> moments(depth.size());
    for (std::size_t i = 0; i < depth.size(); ++i)
        moments[i] = storedMoments(technique.encode(momentDepth(depth[i], convention), uniforms), technique, bits);
    const std::vector<float> weights = blurWeights(blurWidthTexels);
    const int r = int(weights.size() / 2);
    if (r == 0) return moments;
    const auto at = [resolution](int x, int y) { return std::size_t(y) * std::size_t(resolution) + std::size_t(x); };
    std::vector<glm::vec4> pass(moments.size());
    for (int dir = 0; dir < 2; ++dir) {
        for (int y = 0; y < resolution; ++y)
            for (int x = 0; x < resolution; ++x) {
                glm::vec4 sum(0.0f);
                for (int i = -r; i <= r; ++i) {
                    const int sx = dir == 0 ? std::clamp(x + i, 0, resolution - 1) : x;
                    const int sy = dir == 1 ? std::clamp(y + i, 0, resolution - 1) : y;
                    sum += weights[std::size_t(std::abs(i) + r)] * moments[at(sx, sy)];
                }
                pass[at(x, y)] = storedMoments(sum, technique, bits);
            }
        std::swap(moments, pass);
    }
    return moments;
}

glm::vec4 emptyMoments(const FilterSettings& filter) {
    const MomentTechnique& technique = *filterTechnique(filter.kind).moments;
    return storedMoments(technique.encode(1.0f, technique.uniforms(filter)), technique, filter.momentBits);
}

bool isEmptyMoments(const glm::vec4& stored, const glm::vec4& empty) {
    // moments.comp.glsl's emptyMoments: one storage step (fp16 near 1: 2^-11) relative, beyond float rounding.
    return std::abs(stored.x - empty.x) <= 1e-3f * std::max(1.0f, std::abs(empty.x));
}

std::vector<glm::vec4> momentsMipLevel(const std::vector<glm::vec4>& level, int size, const FilterSettings& filter) {
    const MomentTechnique& technique = *filterTechnique(filter.kind).moments;
    const glm::vec4 empty = emptyMoments(filter);
    const int below = std::max(size / 2, 1);
    const auto at = [&](int x, int y) {
        return level[std::size_t(std::min(y, size - 1)) * std::size_t(size) + std::size_t(std::min(x, size - 1))];
    };
    std::vector<glm::vec4> out(std::size_t(below) * std::size_t(below));
    for (int y = 0; y < below; ++y)
        for (int x = 0; x < below; ++x) {
            // The shader's order: the texels holding a caster summed from (0, 0), (1, 0), (0, 1), (1, 1), then / n.
            glm::vec4 sum(0.0f);
            float n = 0.0f;
            for (int i = 0; i < 4; ++i) {
                const glm::vec4 m = at(2 * x + (i & 1), 2 * y + (i >> 1));
                if (isEmptyMoments(m, empty)) continue;
                sum += m;
                n += 1.0f;
            }
            out[std::size_t(y) * std::size_t(below) + std::size_t(x)] =
                n > 0.0f ? storedMoments(sum / n, technique, filter.momentBits) : empty;
        }
    return out;
}

}  // namespace shadowlab
