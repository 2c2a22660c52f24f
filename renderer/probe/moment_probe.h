#pragma once
// The pixel probe's mirror of a moments technique's lookup (shaders/shadow/moments_lookup.glsl): the view's stored
// moments (and mip levels) read back around the lookup, weighted bilinearly (trilinearly at the pixel's footprint's
// level with filter.momentMips), given to the technique's CPU mirror (shading/filters/).
#include "frame/renderer.h"
#include "probe/pixel_footprint.h"
#include "probe/pixel_probe.h"

#include <optional>

namespace shadowlab {

struct MomentLookupGeometry {
    const LightSpace* light = nullptr;  // the view read
    glm::dvec3 lookup{0.0};             // render-origin-relative, after the normal offset
    std::optional<PositionDerivatives> derivatives;  // the surface position's dFdxFine / dFdyFine at the pixel
};

// Fills r's moment fields, taps[0] (the four texels of the level read), shadowCpu / Low / High (the GPU's 8-bit
// weights either way, its level within 1/64) and tolerance. Needs r's lightTexture, receiverDepth, resolution,
// inCone, insideMap, addressMode and filter.
void probeMomentLookup(PixelProbeReport& r, const Renderer& renderer, const ShadowViewId& view,
                       const Settings& settings, const MomentLookupGeometry& geometry);

}  // namespace shadowlab
