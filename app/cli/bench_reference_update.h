#pragma once
// `shadowlab bench --reference-update`: what following an animation step costs the exact reference (Embree, on the
// CPU). The scene is posed at animation.time (t) and t + 1/30 s; the median time of
//  - an update after one instance moved (the first one the step moves; EmbreeScene::updateTransforms: its transform
//    set, the top level re-committed, no mesh BVH built),
//  - an update after the whole step (every instance the animation moves),
//  - a full build at the new pose (what a reference without the update path does: every mesh BVH and the top level),
// each alternating between the two poses so every update really moves something; the median and the fastest of
// each (on a shared machine the fastest shows the cost without waits for a core). Needs a scene with an animation
// (builtin:city-traffic).
#include "cli/bench_command.h"

#include <string>

namespace shadowlab::cli {

int runBenchReferenceUpdate(const BenchOptions& options);

// The CPU the reference benches' figures were taken on (/proc/cpuinfo's first model name).
std::string cpuName();

}  // namespace shadowlab::cli
