#include "views/cascade_scroll.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace shadowlab {

CascadeScroll cascadeScroll(const glm::dmat4& before, const glm::dmat4& now, int resolution) {
    // The depth passes draw through the float matrix: the rotation, size and depth terms must be the same floats, or
    // the moved texels would not be the ones a full draw stores.
    const glm::mat4 a(before), b(now);
    for (int c = 0; c < 4; ++c)
        if (a[c][2] != b[c][2] || a[c][3] != b[c][3])
            return {std::nullopt, "its depth range or the light's direction changed"};
    for (int c = 0; c < 3; ++c)
        if (a[c][0] != b[c][0] || a[c][1] != b[c][1])
            return {std::nullopt, "its size or the light's direction changed"};
    // A clip-space x or y offset of 2 / resolution is one texel.
    int texels[2] = {0, 0};
    for (int axis = 0; axis < 2; ++axis) {
        const double t = (now[3][axis] - before[3][axis]) * 0.5 * double(resolution);
        const double whole = std::round(t);
        if (!(std::abs(t - whole) <= 1e-6)) {
            char text[64];
            std::snprintf(text, sizeof text, "it moved by %.3g texels, not whole ones", t);
            return {std::nullopt, text};
        }
        if (std::abs(whole) >= double(resolution)) return {std::nullopt, "it moved by a whole map or more"};
        texels[axis] = int(whole);
    }
    return {TexelShift{texels[0], texels[1]}, ""};
}

TexelRect scrollSource(const TexelShift& s, int n) {
    return {std::max(0, -s.dx), std::max(0, -s.dy), n - std::max(0, s.dx), n - std::max(0, s.dy)};
}

TexelRect scrollTarget(const TexelShift& s, int n) {
    return {std::max(0, s.dx), std::max(0, s.dy), n - std::max(0, -s.dx), n - std::max(0, -s.dy)};
}

std::vector<TexelRect> exposedStrips(const TexelShift& s, int n) {
    const TexelRect kept = scrollTarget(s, n);
    std::vector<TexelRect> strips;
    // The columns left of or right of what was kept (full height), then the rows below or above it (kept's width).
    if (kept.x0 > 0) strips.push_back({0, 0, kept.x0, n});
    if (kept.x1 < n) strips.push_back({kept.x1, 0, n, n});
    if (kept.y0 > 0) strips.push_back({kept.x0, 0, kept.x1, kept.y0});
    if (kept.y1 < n) strips.push_back({kept.x0, kept.y1, kept.x1, n});
    return strips;
}

std::vector<CascadePage> cascadePages(const LightSpace& cascade, const TexelRect& region) {
    const int n = cascade.resolution;
    const double texel = cascade.texelWorldSize;
    if (cascade.perspective || !(texel > 0.0) || region.empty()) return {};
    // The map's texel 0 in the light's global texel grid: the cascade's centre (-view[3].xy) is a whole texel.
    long long origin[2];
    for (int axis = 0; axis < 2; ++axis) {
        const double centre = -cascade.view[3][axis] / texel;
        if (!(std::abs(centre - std::round(centre)) <= 1e-6) || !(std::abs(centre) < 1e15)) return {};
        origin[axis] = (long long)std::llround(centre) - n / 2;
    }
    if (n % 2 != 0) return {};
    const int page = n % kPagesAcross == 0 ? n / kPagesAcross : n;
    auto floorDiv = [](long long a, long long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); };
    std::vector<CascadePage> pages;
    const long long gx0 = origin[0] + region.x0, gx1 = origin[0] + region.x1;  // [gx0, gx1) global
    const long long gy0 = origin[1] + region.y0, gy1 = origin[1] + region.y1;
    for (long long b = floorDiv(gy0, page); b * page < gy1; ++b)
        for (long long a = floorDiv(gx0, page); a * page < gx1; ++a) {
            const long long px = a * page, py = b * page;  // the page's texel 0, global
            CascadePage p;
            p.inMap = {int(std::max(gx0, px) - origin[0]), int(std::max(gy0, py) - origin[1]),
                       int(std::min(gx1, px + page) - origin[0]), int(std::min(gy1, py + page) - origin[1])};
            p.inPage = {int(p.inMap.x0 + origin[0] - px), int(p.inMap.y0 + origin[1] - py),
                        int(p.inMap.x1 + origin[0] - px), int(p.inMap.y1 + origin[1] - py)};
            // The page's light space: its centre from its global texels alone, the cascade's rotation and depths.
            p.space = cascade;
            p.space.view[3][0] = -(double(px) + 0.5 * page) * texel;
            p.space.view[3][1] = -(double(py) + 0.5 * page) * texel;
            const double scale = double(n) / double(page);
            p.space.projection[0][0] *= scale;
            p.space.projection[1][1] *= scale;
            p.space.orthoSize = cascade.orthoSize / scale;
            p.space.resolution = page;
            p.space.position = cascade.position + (glm::dvec3(glm::transpose(glm::dmat3(cascade.view)) *
                                                              glm::dvec3(cascade.view[3][0] - p.space.view[3][0],
                                                                         cascade.view[3][1] - p.space.view[3][1], 0.0)));
            pages.push_back(p);
        }
    return pages;
}

std::string describeScroll(const TexelShift& s, int n) {
    const double total = double(n) * double(n);
    const double reused = total > 0.0 ? double(scrollTarget(s, n).area()) / total : 0.0;
    char text[96];
    std::snprintf(text, sizeof text, "scrolled %d,%d texels: %.1f %% reused", s.dx, s.dy, 100.0 * reused);
    return text;
}

}  // namespace shadowlab
