#pragma once
// The texel a world blur width (filter.blurUnit world) is divided by: a directional view's texel, a perspective
// view's at the middle of its depth range. The moments pass (frame/renderer.cpp) and the export both use it.
#include "light/light_space.h"

namespace shadowlab {

inline double blurTexelWorldSize(const LightSpace& space) {
    return space.texelSizeAt(0.5 * (space.nearPlane + space.farPlane));
}

}  // namespace shadowlab
