// Poisson disk: 16 bilinear comparisons spread over a disk of filter.poissonRadius texels: soft, unbanded
// penumbrae.
#include "shading/filters/filter_technique.h"

#include "shading/filter_taps.h"

namespace shadowlab {

const FilterTechnique& poissonFilter() {
    static const FilterTechnique technique{
        FilterKind::Poisson, "poisson", true,
        [](const FilterSettings&) { return std::vector<glm::vec2>(poissonDisk().begin(), poissonDisk().end()); },
        [](const FilterSettings& filter) { return filter.poissonRadius; },
        // One more texel: each tap's bilinear comparison reads the next texel too.
        [](const FilterSettings& filter) { return double(filter.poissonRadius) + 1.0; },
        /*gridRadius=*/nullptr, /*receiverPlane=*/true, {"filter.poissonRadius"}};
    return technique;
}

}  // namespace shadowlab
