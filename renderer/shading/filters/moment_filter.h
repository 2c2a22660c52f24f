#pragma once
// What the moments techniques (VSM, EVSM2/4, MSM) share: one bilinear read of the filtered moments at the lookup, a
// reach of the blur's half width, the storage and blur keys, and the CPU halves of their GLSL helpers
// (shaders/shadow/techniques/chebyshev.glsl).
#include "shading/filters/filter_technique.h"

#include <initializer_list>
#include <string>

namespace shadowlab {

// A moments technique's FilterTechnique: `ownKeys` follow the shared storage and blur keys.
FilterTechnique momentsFilter(FilterKind kind, const char* name, std::initializer_list<const char*> ownKeys,
                              const MomentTechnique& moments);

// The trade-off ranges the moments techniques share (each technique's file lists the ones it searches): the variance
// floor over decades (too low: acne on slopes and fp16 noise; too high: bleeding) and the bleeding reduction (too
// low: light in the umbra where casters overlap; too high: darker, narrower penumbrae).
inline const TradeOffRange kMinVarianceTradeOff{"filter.minVariance", 1e-7, 1e-3, 5, /*geometric=*/true};
inline const TradeOffRange kBleedReductionTradeOff{"filter.bleedReduction", 0.0, 0.6, 7};

// A moments technique's storage as a GLSL image format ("rg16f", "rg32f", "rgba16f", "rgba32f", "rgba16": MSM's
// quantized 16 bits are unorm): the one choice the moments pass allocates (shadow/moments_pass.h's
// momentInternalFormat) and the export writes. "" for a technique without moments.
std::string momentImageFormat(const FilterTechnique& technique, int momentBits);

// How many mip levels a moments map of `resolution` has: every level down to 1x1 with filter.momentMips, else 1 (the
// moments pass allocates them; the export writes them).
int momentLevels(int resolution, bool mips);

// Chebyshev's one-tailed upper bound of the lit share for a receiver at `z` over moments (mean, E[x^2]), variance at
// least `minVariance` (chebyshev.glsl's chebyshevUpperBound); 1 when the receiver is not beyond the mean.
float chebyshevUpperBound(float mean, float meanSquare, float z, float minVariance);
// Light-bleeding reduction: shares below `amount` become 0, the rest is rescaled to [0, 1] (chebyshev.glsl).
float reduceBleeding(float pMax, float amount);

}  // namespace shadowlab
