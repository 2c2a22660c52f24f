#pragma once
// A viewable 8-bit picture of a depth map: the stored depths stretched over their used range (cleared texels, at
// depth 1, show white), so a shadow map of a small scene in a deep volume is not a flat grey.
#include <cstdint>
#include <vector>

namespace shadowlab {

struct DepthRange {
    float min = 0.0f;
    float max = 1.0f;  // over texels below 1 (written by a caster); {0,1} if none
};

DepthRange writtenDepthRange(const std::vector<float>& depth);
std::vector<std::uint8_t> depthToGray(const std::vector<float>& depth, DepthRange range);

}  // namespace shadowlab
