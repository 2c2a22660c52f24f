#include "image/depth_visualization.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

DepthRange writtenDepthRange(const std::vector<float>& depth) {
    DepthRange range{1.0f, 0.0f};
    for (float d : depth) {
        if (!std::isfinite(d) || d >= 1.0f) continue;
        range.min = std::min(range.min, d);
        range.max = std::max(range.max, d);
    }
    if (range.min > range.max) return {0.0f, 1.0f};
    if (range.max - range.min < 1e-7f) range.max = range.min + 1e-7f;
    return range;
}

std::vector<std::uint8_t> depthToGray(const std::vector<float>& depth, DepthRange range) {
    std::vector<std::uint8_t> gray(depth.size());
    const float scale = 1.0f / (range.max - range.min);
    for (std::size_t i = 0; i < depth.size(); ++i) {
        const float d = depth[i];
        float t = d >= 1.0f || !std::isfinite(d) ? 1.0f : std::clamp((d - range.min) * scale, 0.0f, 1.0f);
        // Near casters dark, far ones light; the cleared background pure white.
        gray[i] = std::uint8_t(std::lround(d >= 1.0f ? 255.0f : t * 235.0f));
    }
    return gray;
}

}  // namespace shadowlab
