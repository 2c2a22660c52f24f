#pragma once
// How much one unit of D3D DepthBias moves the compared depth, in shadow-map texels, so the tuner can search in
// texels (the same for every scene size) and write DepthBias back. Mirrors the renderer's BiasAmount
// (FrameStats::bias.constantTexels = depthBias x this); a test keeps the two equal.
#include "light/light_space.h"
#include "settings/settings.h"

namespace shadowlab {

double depthBiasUnitTexels(const LightSpace& light, DepthFormat format);

}  // namespace shadowlab
