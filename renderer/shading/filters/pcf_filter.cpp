// Grid PCF: filter.kernel x filter.kernel nearest-texel comparisons, one texel apart, averaged (row by row).
#include "shading/filters/filter_technique.h"

namespace shadowlab {

const FilterTechnique& pcfFilter() {
    static const FilterTechnique technique{
        FilterKind::Pcf, "pcf", false,
        [](const FilterSettings& filter) {
            std::vector<glm::vec2> taps;
            const int r = filter.kernel / 2;
            for (int y = -r; y <= r; ++y)
                for (int x = -r; x <= r; ++x) taps.emplace_back(float(x), float(y));
            return taps;
        },
        [](const FilterSettings&) { return 1.0f; },
        [](const FilterSettings& filter) { return double(filter.kernel - 1) / 2.0; },
        [](const FilterSettings& filter) { return filter.kernel / 2; },
        /*receiverPlane=*/true, {"filter.kernel"}};
    return technique;
}

}  // namespace shadowlab
