#include "shading/filters/moments_mirror.h"

#include "shading/filters/cube_face_frame.h"

#include <glm/geometric.hpp>
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

namespace {

// The conversion: each depth's moments, stored at the precision.
std::vector<glm::vec4> unblurredMoments(const std::vector<float>& depth, const MomentDepthConvention& convention,
                                        const FilterSettings& filter) {
    const MomentTechnique& technique = *filterTechnique(filter.kind).moments;
    const glm::vec4 uniforms = technique.uniforms(filter);
    std::vector<glm::vec4> moments(depth.size());
    for (std::size_t i = 0; i < depth.size(); ++i)
        moments[i] = storedMoments(technique.encode(momentDepth(depth[i], convention), uniforms), technique,
                                   filter.momentBits);
    return moments;
}

std::size_t mirrorTexelIndex(int x, int y, int resolution) {
    return std::size_t(y) * std::size_t(resolution) + std::size_t(x);
}

}  // namespace

std::vector<glm::vec4> momentsOfDepth(const std::vector<float>& depth, int resolution,
                                      const MomentDepthConvention& convention, const FilterSettings& filter,
                                      double blurWidthTexels) {
    const MomentTechnique& technique = *filterTechnique(filter.kind).moments;
    std::vector<glm::vec4> moments = unblurredMoments(depth, convention, filter);
    const std::vector<float> weights = blurWeights(blurWidthTexels);
    const int r = int(weights.size() / 2);
    if (r == 0) return moments;
    std::vector<glm::vec4> pass(moments.size());
    for (int dir = 0; dir < 2; ++dir) {
        for (int y = 0; y < resolution; ++y)
            for (int x = 0; x < resolution; ++x) {
                glm::vec4 sum(0.0f);
                for (int i = -r; i <= r; ++i) {
                    const int sx = dir == 0 ? std::clamp(x + i, 0, resolution - 1) : x;
                    const int sy = dir == 1 ? std::clamp(y + i, 0, resolution - 1) : y;
                    sum += weights[std::size_t(std::abs(i) + r)] * moments[mirrorTexelIndex(sx, sy, resolution)];
                }
                pass[mirrorTexelIndex(x, y, resolution)] = storedMoments(sum, technique, filter.momentBits);
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

CubeMoments momentsOfCube(const std::array<std::vector<float>, 6>& depth, int resolution,
                          const MomentDepthConvention& convention, const FilterSettings& filter,
                          double blurWidthTexels) {
    const MomentTechnique& technique = *filterTechnique(filter.kind).moments;
    CubeMoments raw;
    for (int f = 0; f < 6; ++f) raw[std::size_t(f)] = unblurredMoments(depth[std::size_t(f)], convention, filter);
    const std::vector<float> weights = blurWeights(blurWidthTexels);
    const int r = int(weights.size() / 2);
    if (r == 0) return raw;
    const float step = 1.0f / float(resolution);
    // Texel (x, y) of `face` blurred: tap i at tapOf(i) texels across its frame, read from read(tap, frame)'s faces.
    const auto blurred = [&](int face, int x, int y, auto&& tapOf, auto&& read) {
        const CubeFaceFrame frame = cubeFaceFrame(cubeTexelDirection(face, x, y, resolution), step);
        glm::vec4 sum(0.0f);
        for (int i = -r; i <= r; ++i) {
            const glm::vec3 tap = cubeFaceTap(frame, tapOf(i));
            const CubeTexel t = nearestCubeTexel(glm::dvec3(tap), resolution);
            sum += weights[std::size_t(std::abs(i) + r)] * read(tap, frame)[std::size_t(t.face)][mirrorTexelIndex(t.x, t.y, resolution)];
        }
        return storedMoments(sum, technique, filter.momentBits);
    };
    // First pass: each face along its frame's s (cube 0) and t (cube 1; only within r of an edge, where it is read).
    std::array<CubeMoments, 2> first;
    for (int axis = 0; axis < 2; ++axis)
        for (int f = 0; f < 6; ++f) {
            std::vector<glm::vec4>& out = first[std::size_t(axis)][std::size_t(f)];
            out.assign(raw[std::size_t(f)].size(), glm::vec4(0.0f));
            for (int y = 0; y < resolution; ++y)
                for (int x = 0; x < resolution; ++x) {
                    if (axis == 1 && std::min({x, y, resolution - 1 - std::max(x, y)}) > r) continue;
                    out[mirrorTexelIndex(x, y, resolution)] = blurred(
                        f, x, y, [&](int i) { return axis == 0 ? glm::vec2(float(i), 0.0f) : glm::vec2(0.0f, float(i)); },
                        [&](const glm::vec3&, const CubeFaceFrame&) -> const CubeMoments& { return raw; });
                }
        }
    // Second pass: along t, each tap reading its face's first-pass blur along this face's s (the same world axis).
    CubeMoments out;
    for (int f = 0; f < 6; ++f) {
        out[std::size_t(f)].resize(raw[std::size_t(f)].size());
        for (int y = 0; y < resolution; ++y)
            for (int x = 0; x < resolution; ++x)
                out[std::size_t(f)][mirrorTexelIndex(x, y, resolution)] = blurred(
                    f, x, y, [](int i) { return glm::vec2(0.0f, float(i)); },
                    [&](const glm::vec3& tap, const CubeFaceFrame& frame) -> const CubeMoments& {
                        return first[std::abs(glm::dot(cubeFaceFrame(tap, step).s, frame.s)) > 0.5f ? 0 : 1];
                    });
    }
    return out;
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
