// Point sampling: one nearest-texel comparison. Hard edges, the staircase of the map's texels.
#include "shading/filters/filter_technique.h"

namespace shadowlab {

const FilterTechnique& pointFilter() {
    static const FilterTechnique technique{
        FilterKind::Point, "point", false, [](const FilterSettings&) { return std::vector<glm::vec2>{{0.0f, 0.0f}}; },
        [](const FilterSettings&) { return 1.0f; }, [](const FilterSettings&) { return 0.0; }};
    return technique;
}

}  // namespace shadowlab
