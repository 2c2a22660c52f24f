#pragma once
// The pixel probe's mirror of a moments technique's lookup (shaders/shadow/moments_lookup.glsl): the view's stored
// moments read back around the lookup, weighted bilinearly, given to the technique's CPU mirror (shading/filters/).
#include "frame/renderer.h"
#include "probe/pixel_probe.h"

namespace shadowlab {

// Fills r's moment fields, taps[0] (the four texels), shadowCpu / Low / High (the GPU's 8-bit bilinear weights
// either way) and tolerance. Needs r's lightTexture, receiverDepth, resolution, reversedZ, inCone and filter.
void probeMomentLookup(PixelProbeReport& r, const Renderer& renderer, const ShadowViewId& view,
                       const Settings& settings);

}  // namespace shadowlab
