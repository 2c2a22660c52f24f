#pragma once
// The taps the main pass's shadow filter reads around the lookup, in texels, from the filter technique
// (shading/filters/): the one source for main.frag.glsl (as #defines) and for the pixel probe, which recomputes S.
#include "settings/settings.h"

#include <glm/ext/vector_double2.hpp>
#include <glm/vec2.hpp>

#include <array>
#include <string>
#include <vector>

namespace shadowlab {

inline constexpr int kPoissonTaps = 16;
// Points in the unit disk; the shader scales them by filter.poissonRadius texels.
const std::array<glm::vec2, kPoissonTaps>& poissonDisk();

struct FilterTap {
    glm::dvec2 offsetTexels{0.0};  // added to the lookup's texture coordinate, times 1 / resolution
    bool bilinear = false;         // compared through the sampler's bilinear filter (2x2 texels), else one texel
};

// Every tap of `filter`, in the shader's order; each carries 1/N of S. Offsets are computed in float, as the shader
// does (Poisson: disk x radius).
std::vector<FilterTap> filterTaps(const FilterSettings& filter);

// Whether the filter's comparisons use the sampler's bilinear filter (the shadow map's sampler is set from this).
bool filterIsBilinear(FilterKind kind);

// The #defines main.frag.glsl takes its filter from: FILTER_TAPS and FILTER_TAP_OFFSETS (unscaled; the shader
// multiplies by uFilterScale, the technique's scale).
std::vector<std::string> filterDefines(const FilterSettings& filter);

}  // namespace shadowlab
