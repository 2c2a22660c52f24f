#pragma once
// The human-readable summary of a frame that the CLI prints: passes and why, timings, bias in several units.
#include "context/gl_info.h"
#include "frame/frame_stats.h"
#include "scene/scene.h"

#include <ostream>

namespace shadowlab::cli {

void printFrameReport(std::ostream& out, const Scene& scene, const GlInfo& info, const FrameStats& stats);

}  // namespace shadowlab::cli
