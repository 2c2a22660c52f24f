#include "views/caster_motion.h"

#include <glm/ext/vector_double4.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

void TexelRect::extend(const TexelRect& r) {
    if (r.empty()) return;
    if (empty()) {
        *this = r;
        return;
    }
    x0 = std::min(x0, r.x0);
    y0 = std::min(y0, r.y0);
    x1 = std::max(x1, r.x1);
    y1 = std::max(y1, r.y1);
}

TexelRect casterTexels(const CasterSphere& caster, const LightSpace& space) {
    const int n = space.resolution;
    const TexelRect whole{0, 0, n, n};
    if (!caster.finite) return whole;
    const glm::dvec3 c = glm::dvec3(space.view * glm::dvec4(caster.center, 1.0));
    const double r = caster.radius;
    // A perspective view divides by the distance along its axis: a box reaching its eye's plane has no bound.
    if (space.perspective && -c.z - r <= 1e-9 * std::max(1.0, r)) return whole;
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 corner(c.x + ((i & 1) ? r : -r), c.y + ((i & 2) ? r : -r), c.z + ((i & 4) ? r : -r), 1.0);
        const glm::dvec4 clip = space.projection * corner;
        for (int a = 0; a < 2; ++a) {
            const double ndc = clip[a] / clip.w;
            lo[a] = std::min(lo[a], ndc);
            hi[a] = std::max(hi[a], ndc);
        }
    }
    auto texel = [n](double ndc) { return (ndc * 0.5 + 0.5) * double(n); };
    auto bound = [n](double t) { return int(std::clamp(t, -1.0, double(n) + 1.0)); };
    TexelRect rect{bound(std::floor(texel(lo[0])) - 1.0), bound(std::floor(texel(lo[1])) - 1.0),
                   bound(std::ceil(texel(hi[0])) + 1.0), bound(std::ceil(texel(hi[1])) + 1.0)};
    rect.x0 = std::max(rect.x0, 0);
    rect.y0 = std::max(rect.y0, 0);
    rect.x1 = std::min(rect.x1, n);
    rect.y1 = std::min(rect.y1, n);
    if (rect.empty()) return {};
    return rect;
}

}  // namespace shadowlab
