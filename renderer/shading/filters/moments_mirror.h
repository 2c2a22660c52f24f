#pragma once
// The moments pass on the CPU, for tests and the probe: a depth layer converted to the technique's moments, stored at
// its precision, blurred by the box of blurWeights (horizontal, then vertical, edge texels repeated, each result
// stored at the precision again), as shaders/moments.comp.glsl computes them.
#include "shading/filters/filter_technique.h"

#include <glm/vec4.hpp>

#include <vector>

namespace shadowlab {

// One value as the storage holds it: fp32 as is, fp16 rounded to half, unorm16 clamped to [0, 1] in 1/65535 steps.
glm::vec4 storedMoments(const glm::vec4& value, const MomentTechnique& technique, int momentBits);

// `depth`: resolution x resolution stored depths (row 0 = bottom), in the map's convention (reversedZ: near 1).
std::vector<glm::vec4> momentsOfDepth(const std::vector<float>& depth, int resolution, bool reversedZ,
                                      const FilterSettings& filter, double blurWidthTexels);

}  // namespace shadowlab
