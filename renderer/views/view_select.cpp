#include "views/view_select.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>

namespace shadowlab {

int cubeFaceOf(const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    return 2 * axis + (d[axis] < 0.0 ? 1 : 0);
}

ViewChoice selectCascade(double depth, std::span<const double> farDepths, std::span<const double> blendStarts) {
    for (std::size_t i = 0; i < farDepths.size(); ++i) {
        if (!(depth <= farDepths[i])) continue;
        ViewChoice choice{int(i)};
        if (i + 1 < farDepths.size() && depth > blendStarts[i]) {
            choice.next = int(i + 1);
            choice.weight = (depth - blendStarts[i]) / (farDepths[i] - blendStarts[i]);
        }
        return choice;
    }
    return {};
}

ViewChoice selectView(const std::vector<ShadowView>& lightViews, const glm::dvec3& p) {
    if (lightViews.empty()) return {};
    if (lightViews.front().kind == ShadowViewKind::Cascade) {
        // Asked per pixel by the accuracy meter and the boundary search: no allocation (a light has at most 4).
        std::array<double, 4> far{}, blend{};
        const std::size_t count = std::min(lightViews.size(), far.size());
        for (std::size_t v = 0; v < count; ++v) {
            far[v] = lightViews[v].slice.farDepth;
            blend[v] = lightViews[v].slice.blendStart;
        }
        return selectCascade(lightViews.front().slice.camera.depthOf(p), std::span(far).first(count),
                             std::span(blend).first(count));
    }
    if (lightViews.front().kind == ShadowViewKind::CubeFace) {
        const int face = cubeFaceOf(p - lightViews.front().space.position);
        for (std::size_t v = 0; v < lightViews.size(); ++v)
            if (lightViews[v].index == face) return {int(v)};
        return {};
    }
    return {0};
}

const ShadowView* viewHolding(const std::vector<ShadowView>& lightViews, const glm::dvec3& p) {
    const ViewChoice choice = selectView(lightViews, p);
    return choice.view < 0 ? nullptr : &lightViews[std::size_t(choice.view)];
}

}  // namespace shadowlab
