#pragma once
// The maps of one array share a MapGroup: 2D or cube, size, format and depth convention (an array's sampler
// compares LEQUAL or GEQUAL, so one convention per array).
#include "settings/settings.h"

#include <compare>
#include <string>

namespace shadowlab {

struct MapGroup {
    bool cube = false;
    int resolution = 0;
    DepthFormat format = DepthFormat::D32F;
    bool reversedZ = false;
    auto operator<=>(const MapGroup&) const = default;
};

// The array a casting light's views go into: a point light's cube faces into a cube array, every other view into a
// 2D array (the planner groups views by it; the main pass's variant key counts the arrays by it).
inline MapGroup mapGroupOf(const LightSettings& light) {
    return {light.type == LightType::Point, light.shadow.resolution, light.shadow.format, light.shadow.reversedZ};
}

// "" when the shadow.resolution key and this GPU allow `resolution`, else the message saying the range and `kept`.
std::string shadowResolutionRefusal(int resolution, int maxTextureSize, const std::string& kept);

}  // namespace shadowlab
