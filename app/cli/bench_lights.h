#pragma once
// `shadowlab bench --lights`: what many lights cost, and what the shadow planner saves. With the settings' lights
// (a preset of several lights, or --set lights.N.*): every view's time when all render, the views a static frame
// renders (none) and a frame that moves one light renders (only its views), and the main pass with 1, 2, 4, 8 ...
// of the lights shadowed next to the same lights unshadowed: the difference is the shadow taps' cost.
#include "cli/bench_command.h"

namespace shadowlab::cli {

int runBenchLights(const BenchOptions& options);

}  // namespace shadowlab::cli
