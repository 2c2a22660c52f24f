#include "probe/moment_probe.h"

#include "shading/filters/cube_face_frame.h"
#include "shading/filters/filter_technique.h"
#include "shading/filters/moments_mirror.h"
#include "shadow/moments_pass.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace shadowlab {

void probeMomentLookup(PixelProbeReport& r, const Renderer& renderer, const ShadowViewId& view,
                       const Settings& settings, const MomentLookupGeometry& geometry) {
    const FilterTechnique& technique = filterTechnique(r.filter.kind);
    const MomentTechnique& m = *technique.moments;
    const glm::vec4 uniforms = m.uniforms(r.filter);
    const LightSpace& light = *geometry.light;
    const int res = r.resolution;
    r.momentLookup = true;
    r.taps.clear();

    // The mip level (moments_lookup.glsl's momentLevel): the lookup's step in the map across the pixel's quad
    // neighbours, in texels, log2 of the larger, within the map's levels.
    const int maxLevel = momentLevels(res, true) - 1;
    const bool mips = r.filter.momentMips;
    double level = 0.0;
    if (mips && geometry.derivatives) {
        const auto texStep = [&](const glm::dvec3& d) {
            const glm::dvec3 moved = light.textureOf(light.viewProjection() * glm::dvec4(geometry.lookup + d, 1.0));
            return glm::length(glm::dvec2(moved) - glm::dvec2(r.lightTexture));
        };
        const double rho = std::max(texStep(geometry.derivatives->dx), texStep(geometry.derivatives->dy)) * res;
        level = std::clamp(std::log2(std::max(rho, 1e-300)), 0.0, double(maxLevel));
        r.momentLevel = level;
    }

    // Stored moments, read back a few texels at a time per level (and cube face); outside the map (clamp-to-border)
    // the border depth's moments. A cube face is filtered seamlessly: a texel beyond its edge is the neighbouring
    // face's (cube_face_frame.h), and beyond both edges (a cube corner) the mean of the three texels around the
    // corner (the specification's recommendation, llvmpipe's); `corner` 1-3 takes one of them alone instead, for
    // the bounds of an implementation that does otherwise.
    const glm::vec4 border = m.encode(settings.sampler.borderDepth, uniforms);
    const bool cube = view.kind == ShadowViewKind::CubeFace;
    struct Block {
        int x0 = 0, y0 = 0, w = 0, h = 0;
        std::vector<glm::vec4> texels;
    };
    std::map<std::pair<int, int>, Block> blocks;  // by level and face
    bool missing = false, cornerRead = false;
    const auto storedAt = [&](int lvl, int face, int ax, int ay) {
        const int size = std::max(res >> lvl, 1);
        Block& b = blocks[{lvl, face}];
        if (ax < b.x0 || ax >= b.x0 + b.w || ay < b.y0 || ay >= b.y0 + b.h) {
            b.x0 = std::clamp(ax - 1, 0, std::max(size - 4, 0)), b.y0 = std::clamp(ay - 1, 0, std::max(size - 4, 0));
            b.w = std::min(4, size - b.x0), b.h = std::min(4, size - b.y0);
            b.texels = renderer.viewMoments(cube ? ShadowViewId{view.light, view.kind, face} : view, b.x0, b.y0, b.w,
                                            b.h, lvl);
            if (b.texels.size() != std::size_t(b.w * b.h)) {
                missing = true;
                b.w = b.h = 0;
                return border;
            }
        }
        glm::vec4 value = b.texels[std::size_t(ay - b.y0) * std::size_t(b.w) + std::size_t(ax - b.x0)];
        for (int c = m.channels; c < 4; ++c) value[c] = 0.0f;  // RG storage: only its channels count
        return value;
    };
    const auto texelAt = [&](int lvl, int tx, int ty, int corner = 0) {
        const int size = std::max(res >> lvl, 1);
        if (cube) {
            const auto seamless = [&](int x, int y) {
                const CubeTexel at = *seamlessTexel(view.index, x, y, size);
                return storedAt(lvl, at.face, at.x, at.y);
            };
            if (seamlessTexel(view.index, tx, ty, size)) return seamless(tx, ty);
            cornerRead = true;
            const int ix = std::clamp(tx, 0, size - 1), iy = std::clamp(ty, 0, size - 1);
            const glm::vec4 around[3] = {seamless(ix, iy), seamless(tx, iy), seamless(ix, ty)};
            return corner == 0 ? (around[0] + around[1] + around[2]) / 3.0f : around[corner - 1];
        }
        const std::optional<int> ax = addressTexel(tx, size, r.addressMode), ay = addressTexel(ty, size, r.addressMode);
        if (!ax || !ay) return border;
        return storedAt(lvl, view.index, *ax, *ay);
    };

    // Where the GPU reads (float, as moments_lookup.glsl): inside a 2D map, half a texel of the coarser level read
    // from its edge; a cube face at the lookup's direction.
    const float step = 1.0f / float(res);
    const glm::vec2 lookupTex(float(r.lightTexture.x), float(r.lightTexture.y));
    const auto readAt = [&](double lambda) {
        const float edge = 0.5f * step * std::exp2(float(std::ceil(lambda)));
        return r.insideMap && !cube ? glm::clamp(lookupTex, glm::vec2(edge), glm::vec2(1.0f - edge)) : lookupTex;
    };
    // One level's bilinear read; `round` rounds the sub-texel weights as the GPU's 8 bits may (1: both down, 2: both
    // up, 3 / 4: one each way); `corner`: texelAt's.
    const auto bilinear = [&](int lvl, const glm::vec2& tex, int round, int corner) {
        const int size = std::max(res >> lvl, 1);
        const glm::dvec2 u = glm::dvec2(tex) * double(size) - 0.5;
        const glm::ivec2 i0(int(std::floor(u.x)), int(std::floor(u.y)));
        glm::dvec2 f = u - glm::dvec2(i0);
        const auto down = [](double w) { return std::floor(w * 256.0) / 256.0; };
        const auto up = [](double w) { return std::ceil(w * 256.0) / 256.0; };
        if (round) f = {round == 1 || round == 3 ? down(f.x) : up(f.x), round == 1 || round == 4 ? down(f.y) : up(f.y)};
        const glm::vec4 bottom = texelAt(lvl, i0.x, i0.y, corner) * float(1.0 - f.x) +
                                 texelAt(lvl, i0.x + 1, i0.y, corner) * float(f.x);
        const glm::vec4 top = texelAt(lvl, i0.x, i0.y + 1, corner) * float(1.0 - f.x) +
                              texelAt(lvl, i0.x + 1, i0.y + 1, corner) * float(f.x);
        return bottom * float(1.0 - f.y) + top * float(f.y);
    };
    // The trilinear read at level lambda; `levelRound` rounds the levels' weight to 8 bits down (1) or up (2).
    const auto filteredAt = [&](double lambda, int round, int levelRound, int corner = 0) {
        const int low = int(std::floor(lambda));
        double frac = lambda - low;
        if (levelRound == 1) frac = std::floor(frac * 256.0) / 256.0;
        if (levelRound == 2) frac = std::ceil(frac * 256.0) / 256.0;
        const glm::vec2 tex = readAt(lambda);
        const glm::vec4 lower = bilinear(low, tex, round, corner);
        if (frac <= 0.0 || low >= maxLevel) return lower;
        return lower * float(1.0 - frac) + bilinear(low + 1, tex, round, corner) * float(frac);
    };

    // The report's tap: the four texels of the (lower) level read.
    ProbeTap tap;
    tap.bilinear = true;
    {
        const int lvl = int(std::floor(level));
        const int size = std::max(res >> lvl, 1);
        tap.texelCoord = glm::dvec2(readAt(level)) * double(size);
        const glm::dvec2 u = tap.texelCoord - 0.5;
        const glm::ivec2 i0(int(std::floor(u.x)), int(std::floor(u.y)));
        const glm::dvec2 f = u - glm::dvec2(i0);
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                ProbeTexel texel;
                const std::optional<int> ax = addressTexel(i0.x + dx, size, r.addressMode),
                                         ay = addressTexel(i0.y + dy, size, r.addressMode);
                texel.border = !cube && (!ax || !ay);
                texel.texel = texel.border ? glm::ivec2(i0.x + dx, i0.y + dy) : glm::ivec2(*ax, *ay);
                if (cube) {  // the neighbouring face's texel beyond an edge (a corner: shown at the face's own)
                    const std::optional<CubeTexel> at = seamlessTexel(view.index, i0.x + dx, i0.y + dy, size);
                    texel.face = at ? at->face : view.index;
                    texel.texel = at ? glm::ivec2(at->x, at->y) : glm::clamp(i0 + glm::ivec2(dx, dy), 0, size - 1);
                }
                texel.stored = texelAt(lvl, i0.x + dx, i0.y + dy).x;
                texel.weight = (dx ? f.x : 1.0 - f.x) * (dy ? f.y : 1.0 - f.y);
                tap.texels.push_back(texel);
            }
    }

    // The receiver as the moments pass stored depths (near 0, far 1; linear for perspective views).
    const MomentDepthConvention convention{light.reversedZ, light.perspective, float(light.nearPlane),
                                           float(light.farPlane)};
    const float z = momentDepth(float(r.receiverDepth), convention);
    r.momentDepth = z;
    const glm::vec4 filtered = filteredAt(level, 0, 0);
    if (missing) {
        r.error = "no moments stored for " + r.viewName;
        return;
    }
    r.moments = glm::dvec4(filtered);
    const double cone = r.inCone ? 1.0 : 0.0;
    r.shadowCpu = double(m.shadow(filtered, z, uniforms)) * cone;
    r.momentText = m.explain(filtered, z, uniforms);
    // The GPU weighs texels with 8 sub-texel bits (D3D's rules, llvmpipe), and the two levels with 8 bits too: S
    // with each weight rounded either way. Its level comes from float differences of interpolated positions (and
    // its quad's derivative may be the coarse one, of the quad's other row): within 1/64 of a level of ours.
    r.shadowLow = r.shadowHigh = r.shadowCpu;
    std::vector<double> lambdas{level};
    if (mips && level > 0.0) lambdas = {level, std::max(level - 1.0 / 64.0, 0.0), std::min(level + 1.0 / 64.0, double(maxLevel))};
    for (const double lambda : lambdas)
        for (int round = 0; round <= 4; ++round)
            for (int levelRound = 0; levelRound <= (mips ? 2 : 0); ++levelRound)
                for (int corner = 0; corner <= (cornerRead ? 3 : 0); ++corner) {
                    const double s = double(m.shadow(filteredAt(lambda, round, levelRound, corner), z, uniforms)) * cone;
                    r.shadowLow = std::min(r.shadowLow, s);
                    r.shadowHigh = std::max(r.shadowHigh, s);
                }
    // The GPU filters stored values at its own precision (llvmpipe: unorm16 in fixed point): each filtered moment
    // may differ by a couple of storage steps, which MSM's decoding and ill-conditioned bound amplify.
    for (int c = 0; c < m.channels; ++c)
        for (const float sign : {-1.0f, 1.0f}) {
            const float value = filtered[c];
            const float storageStep = r.filter.momentBits == 32 ? std::abs(value) * 1e-6f
                                      : m.unorm16               ? 2.0f / 65535.0f
                                                                : std::abs(value) * 2.0f / 1024.0f;
            glm::vec4 moved = filtered;
            moved[c] = value + sign * storageStep;
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
