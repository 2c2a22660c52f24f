// Hardware 2x2 PCF: one comparison through the sampler's bilinear filter, which compares the four nearest texels
// and blends the results.
#include "shading/filters/filter_technique.h"

namespace shadowlab {

const FilterTechnique& hardware2x2Filter() {
    static const FilterTechnique technique{
        FilterKind::Hardware2x2, "hardware2x2", true,
        [](const FilterSettings&) { return std::vector<glm::vec2>{{0.0f, 0.0f}}; },
        [](const FilterSettings&) { return 1.0f; }, [](const FilterSettings&) { return 1.0; }};
    return technique;
}

}  // namespace shadowlab
