#pragma once
// The depth profile as a chart (LinePlot, for a PNG) and as JSON (every sample's numbers).
#include "image/line_plot.h"
#include "probe/depth_profile.h"

#include <nlohmann/json.hpp>

namespace shadowlab {

// Receiver depth, receiver - bias and the map's texels - bias (a staircase) against the distance along the line;
// acne and Peter Panning samples as shaded bands. Both sides of the shader's comparison move by the same bias, so
// the staircase dips below "receiver - bias" exactly where the comparison says shadowed.
LinePlot depthProfilePlot(const DepthProfile& profile);

nlohmann::json depthProfileToJson(const DepthProfile& profile);

}  // namespace shadowlab
