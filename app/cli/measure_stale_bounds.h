#pragma once
// `shadowlab measure --stale-bounds DEGREES`: what depth bounds one frame late cost (HARD_CASES 20): the frame right
// after the camera turns DEGREES about world up, measured with this frame's bounds (projection.depthBounds sameFrame)
// and with the frame before's (previousFrame); the missing shadows of each (renderer/accuracy/stale_depth_bounds.h).
#include "cli/measure_command.h"

namespace shadowlab::cli {

// Exit code 0 unless it failed (bad option, light 0 not a cascaded directional light, no GL, an unwritable file).
int runMeasureStaleBounds(const MeasureOptions& options);

}  // namespace shadowlab::cli
