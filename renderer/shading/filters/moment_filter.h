#pragma once
// What the moments techniques (VSM, EVSM2/4, MSM) share: one bilinear read of the filtered moments at the lookup, a
// reach of the blur's half width, the storage and blur keys, and the CPU halves of their GLSL helpers
// (shaders/shadow/techniques/chebyshev.glsl).
#include "shading/filters/filter_technique.h"

#include <initializer_list>

namespace shadowlab {

// A moments technique's FilterTechnique: `ownKeys` follow the shared storage and blur keys.
FilterTechnique momentsFilter(FilterKind kind, const char* name, std::initializer_list<const char*> ownKeys,
                              const MomentTechnique& moments);

// Chebyshev's one-tailed upper bound of the lit share for a receiver at `z` over moments (mean, E[x^2]), variance at
// least `minVariance` (chebyshev.glsl's chebyshevUpperBound); 1 when the receiver is not beyond the mean.
float chebyshevUpperBound(float mean, float meanSquare, float z, float minVariance);
// Light-bleeding reduction: shares below `amount` become 0, the rest is rescaled to [0, 1] (chebyshev.glsl).
float reduceBleeding(float pMax, float amount);

}  // namespace shadowlab
