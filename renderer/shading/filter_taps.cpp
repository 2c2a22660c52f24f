#include "shading/filter_taps.h"

#include "shading/filters/filter_technique.h"

#include <cstdio>

namespace shadowlab {

const std::array<glm::vec2, kPoissonTaps>& poissonDisk() {
    static const std::array<glm::vec2, kPoissonTaps> disk = {{
        {-0.94201624f, -0.39906216f}, {0.94558609f, -0.76890725f}, {-0.09418410f, -0.92938870f},
        {0.34495938f, 0.29387760f},   {-0.91588581f, 0.45771432f}, {-0.81544232f, -0.87912464f},
        {-0.38277543f, 0.27676845f},  {0.97484398f, 0.75648379f},  {0.44323325f, -0.97511554f},
        {0.53742981f, -0.47373420f},  {-0.26496911f, -0.41893023f}, {0.79197514f, 0.19090188f},
        {-0.24188840f, 0.99706507f},  {-0.81409955f, 0.91437590f}, {0.19984126f, 0.78641367f},
        {0.14383161f, -0.14100790f},
    }};
    return disk;
}

bool filterIsBilinear(FilterKind kind) { return filterTechnique(kind).bilinear; }

std::vector<FilterTap> filterTaps(const FilterSettings& filter) {
    const FilterTechnique& technique = filterTechnique(filter.kind);
    const float scale = technique.scale(filter);
    std::vector<FilterTap> taps;
    // In float, as the shader computes TAP_OFFSETS[i] * uFilterScale.
    for (const glm::vec2& unit : technique.unitTaps(filter))
        taps.push_back({glm::dvec2(unit * scale), technique.bilinear});
    return taps;
}

std::vector<std::string> filterDefines(const FilterSettings& filter) {
    const std::vector<glm::vec2> taps = filterTechnique(filter.kind).unitTaps(filter);
    std::string values;
    char buf[64];
    for (const glm::vec2& p : taps) {
        // %.9g round-trips a float: the GPU gets exactly the probe's numbers.
        std::snprintf(buf, sizeof buf, "%svec2(%.9g, %.9g)", values.empty() ? "" : ", ", double(p.x), double(p.y));
        values += buf;
    }
    return {"FILTER_TAPS " + std::to_string(taps.size()), "FILTER_TAP_OFFSETS " + values};
}

}  // namespace shadowlab
