#include "probe/moment_probe.h"

#include "shading/filters/filter_technique.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

void probeMomentLookup(PixelProbeReport& r, const Renderer& renderer, const ShadowViewId& view,
                       const Settings& settings) {
    const FilterTechnique& technique = filterTechnique(r.filter.kind);
    const MomentTechnique& m = *technique.moments;
    const glm::vec4 uniforms = m.uniforms(r.filter);
    const int res = r.resolution;
    r.momentLookup = true;
    r.taps.clear();

    // Where the GPU reads (float, as moments_lookup.glsl): inside the map, half a texel from its edge.
    const float step = 1.0f / float(res);
    glm::vec2 tex(float(r.lightTexture.x), float(r.lightTexture.y));
    if (r.insideMap) tex = glm::clamp(tex, glm::vec2(0.5f * step), glm::vec2(1.0f - 0.5f * step));
    ProbeTap tap;
    tap.bilinear = true;
    tap.texelCoord = glm::dvec2(tex) * double(res);
    const glm::dvec2 u = tap.texelCoord - 0.5;
    const glm::ivec2 i0(int(std::floor(u.x)), int(std::floor(u.y)));
    const glm::dvec2 f = u - glm::dvec2(i0);

    // The 2x2 texels, read back once; outside the map (clamp-to-border) the border depth's moments.
    const std::optional<int> x0 = addressTexel(i0.x, res, r.addressMode), x1 = addressTexel(i0.x + 1, res, r.addressMode);
    const std::optional<int> y0 = addressTexel(i0.y, res, r.addressMode), y1 = addressTexel(i0.y + 1, res, r.addressMode);
    const int minX = std::min(x0.value_or(res), x1.value_or(res)), maxX = std::max(x0.value_or(-1), x1.value_or(-1));
    const int minY = std::min(y0.value_or(res), y1.value_or(res)), maxY = std::max(y0.value_or(-1), y1.value_or(-1));
    const int w = maxX >= minX ? maxX - minX + 1 : 0, h = maxY >= minY ? maxY - minY + 1 : 0;
    const std::vector<glm::vec4> stored = renderer.viewMoments(view, minX, minY, w, h);
    if (w * h > 0 && stored.empty()) {
        r.error = "no moments stored for " + r.viewName;
        return;
    }
    const glm::vec4 border = m.encode(settings.sampler.borderDepth, uniforms);
    glm::vec4 texels[2][2];
    for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
            const std::optional<int> ax = dx ? x1 : x0, ay = dy ? y1 : y0;
            ProbeTexel texel;
            texel.border = !ax || !ay;
            texel.texel = texel.border ? glm::ivec2(i0.x + dx, i0.y + dy) : glm::ivec2(*ax, *ay);
            glm::vec4 value = texel.border ? border
                                           : stored[std::size_t(*ay - minY) * std::size_t(w) + std::size_t(*ax - minX)];
            for (int c = m.channels; c < 4; ++c) value[c] = 0.0f;  // RG storage: only its channels count
            texels[dy][dx] = value;
            texel.stored = value.x;
            texel.weight = (dx ? f.x : 1.0 - f.x) * (dy ? f.y : 1.0 - f.y);
            tap.texels.push_back(texel);
        }

    // The receiver in the moments' convention (near 0, far 1: reversed-Z maps were flipped by the moments pass).
    const float z = float(r.reversedZ ? 1.0 - r.receiverDepth : r.receiverDepth);
    r.momentDepth = z;
    const auto lookupAt = [&](double fx, double fy) {
        const glm::vec4 bottom = texels[0][0] * float(1.0 - fx) + texels[0][1] * float(fx);
        const glm::vec4 top = texels[1][0] * float(1.0 - fx) + texels[1][1] * float(fx);
        return bottom * float(1.0 - fy) + top * float(fy);
    };
    const glm::vec4 filtered = lookupAt(f.x, f.y);
    r.moments = glm::dvec4(filtered);
    const double cone = r.inCone ? 1.0 : 0.0;
    r.shadowCpu = double(m.shadow(filtered, z, uniforms)) * cone;
    r.momentText = m.explain(filtered, z, uniforms);
    // The GPU weighs texels with 8 sub-texel bits (D3D's rules, llvmpipe): S with each weight rounded either way.
    r.shadowLow = r.shadowHigh = r.shadowCpu;
    for (const double fx : {std::floor(f.x * 256.0) / 256.0, std::ceil(f.x * 256.0) / 256.0})
        for (const double fy : {std::floor(f.y * 256.0) / 256.0, std::ceil(f.y * 256.0) / 256.0}) {
            const double s = double(m.shadow(lookupAt(fx, fy), z, uniforms)) * cone;
            r.shadowLow = std::min(r.shadowLow, s);
            r.shadowHigh = std::max(r.shadowHigh, s);
        }
    // The GPU filters stored values at its own precision (llvmpipe: unorm16 in fixed point): each filtered moment
    // may differ by a couple of storage steps, which MSM's decoding and ill-conditioned bound amplify.
    for (int c = 0; c < m.channels; ++c)
        for (const float sign : {-1.0f, 1.0f}) {
            const float value = filtered[c];
            const float step = r.filter.momentBits == 32 ? std::abs(value) * 1e-6f
                               : m.unorm16             ? 2.0f / 65535.0f
                                                       : std::abs(value) * 2.0f / 1024.0f;
            glm::vec4 moved = filtered;
            moved[c] = value + sign * step;
            const double s = double(m.shadow(moved, z, uniforms)) * cone;
            r.shadowLow = std::min(r.shadowLow, s);
            r.shadowHigh = std::max(r.shadowHigh, s);
        }
    tap.value = tap.low = tap.high = r.shadowCpu;
    r.taps.push_back(tap);
    // Float rounding of the receiver's depth and the moments' arithmetic (the bound divides small differences).
    r.tolerance = 2e-3;
}

}  // namespace shadowlab
