#pragma once
// `shadowlab bench --planner`: what the shadow planner and a cascade's shadow pass cost.
//  1. The planner alone (this thread's CPU time): the mean time of planShadowViews per frame with 8 lights (two cascaded
//     suns, three spots, three point lights around the scene, each with light 0's shadow-map settings), the camera
//     moving every frame (the cascades re-planned) and still (nothing to render).
//  2. Each cascade's shadow pass (every view forced each frame; the renderer's timing source) against a bare depth
//     draw of the casters it holds (renderer/sweep/bare_depth_draw.h, only those instances), per cascade: the ratio
//     is what the pass adds around the raster. The settings' cascaded lights, else the mix's first sun alone.
#include "cli/bench_command.h"
#include "scene/scene.h"

#include <vector>

namespace shadowlab::cli {

int runBenchPlanner(const BenchOptions& options);

// The planner benchmark's 8 lights for a scene with these bounds (two cascaded suns, three spots, three point
// lights), each with `model`'s shadow-map settings.
std::vector<LightSettings> plannerBenchLights(const Bounds& bounds, const LightSettings& model);

}  // namespace shadowlab::cli
