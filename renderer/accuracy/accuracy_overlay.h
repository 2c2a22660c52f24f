#pragma once
// The error overlay: red = acne (false shadow on a lit receiver), blue = leak (light where the reference is in
// shadow), both darker within k texels of a true boundary (the filter's legitimate blur, not counted), orange =
// faint acne, yellow = the true shadow boundary as a thin line; everything else dimmed (grey: the tool's S x Lambert).
#include "accuracy/accuracy_metrics.h"
#include "accuracy/shadow_boundary.h"

#include <cstdint>
#include <vector>

namespace shadowlab {

// RGBA8, row 0 = top (the buffers' order).
std::vector<std::uint8_t> makeOverlay(int width, int height, const std::vector<PixelClass>& classes,
                                      const std::vector<float>& shadowFactor, const std::vector<float>& lambert,
                                      const std::vector<PixelMark>& marks, const ShadowBoundary& boundary,
                                      float ambient);

}  // namespace shadowlab
