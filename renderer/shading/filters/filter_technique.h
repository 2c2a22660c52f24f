#pragma once
// A shadow filter technique, in one place: how its comparisons are filtered by the sampler, the taps it reads
// (main.frag.glsl gets them as #defines, the pixel probe recomputes S from the same list), the uniform that scales
// them, and how far from the lookup it reads (the accuracy metrics' k). One file per technique under filters/;
// adding one is that file, a FilterKind value, its key name and a line in filter_technique.cpp's table.
#include "settings/settings.h"

#include <glm/vec2.hpp>

#include <vector>

namespace shadowlab {

struct FilterTechnique {
    FilterKind kind;
    const char* name;  // the filter.kind value
    bool bilinear;     // compared through the sampler's bilinear filter (2x2 texels), else one texel per tap
    // Tap offsets in texels before scaling, in the shader's order; each carries 1/N of S.
    std::vector<glm::vec2> (*unitTaps)(const FilterSettings& filter);
    // uFilterScale: multiplies every offset (Poisson: the radius; grids: 1).
    float (*scale)(const FilterSettings& filter);
    // How many texels from the lookup the filter reads: within k of an edge acne and leak are not judged.
    double (*radiusTexels)(const FilterSettings& filter);
    // Optional: when the taps are the square grid -R..R (row by row), R; the shader then loops instead of reading a
    // constant array (much faster for large kernels on some drivers).
    int (*gridRadius)(const FilterSettings& filter) = nullptr;
    // Whether shadow.receiverPlaneBias applies: taps away from the lookup (PCF, Poisson) compare the receiver plane's
    // depth there. A single centred tap has nothing to tilt.
    bool receiverPlane = false;
};

const FilterTechnique& filterTechnique(FilterKind kind);

// The techniques, one per file.
const FilterTechnique& pointFilter();
const FilterTechnique& hardware2x2Filter();
const FilterTechnique& pcfFilter();
const FilterTechnique& poissonFilter();

}  // namespace shadowlab
