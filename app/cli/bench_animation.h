#pragma once
// `shadowlab bench --animation [NAME|INDEX] [--frames N] [--step S]` (issue 22, "What it measures"): the scene's
// animation played frame by frame (frame f at animation.time + f x S), the shadow pass of each frame with the lights'
// own shadow.update (the cached policy) against the same frames with every view re-rendered (everyFrame), per frame
// and per view, with the views each frame rendered and reused; then the last pose once more: a still frame.
// `--cache-error`: the same animation under each policy (everyFrame, onChange, cachedStatic, everyNthFrame N for each
// of --intervals, and cachedStatic with the first moving caster flagged static through casters.static), every frame
// measured against the exact reference at its time (measure's wrong pixels and mean error) and against a full
// re-render of the same frame (the cache error, accuracy/cache_error.h), beside the ms the policy saves; its camera
// sees the first moving caster unless the settings fix the camera (cli/mover_camera.h).
// `--walk DX,DY,DZ`: the camera and its target move by that vector every frame (with or without --animation): stable
// cascades scroll their cached static depth (views/cascade_scroll.h); per frame and view the share of texels
// re-rendered beside the ms, against every cascade re-rendered.
#include "cli/bench_command.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace shadowlab::cli {

struct BenchAnimationOptions {
    std::string animation;  // --animation [NAME|INDEX]: "" = the settings' animation.play
    std::string step;       // seconds per frame, as typed (parsed with a message naming --step)
    std::string time;       // --time SECONDS: the first frame's animation.time, as typed ("" = the settings')
    bool cacheError = false;
    std::vector<int> intervals = {2, 4, 8};  // everyNthFrame's N with --cache-error
    int light = -1;                          // --light N with --cache-error (-1: the only casting light)
    std::string walk;                        // --walk DX,DY,DZ as typed: world units the camera moves a frame
    const CLI::Option* animationOption = nullptr;  // --animation: given (the animation plays) or not (a walk alone)
    bool requested(const CLI::App& bench) const;
};

// Registers --animation, --step, --time, --cache-error, --intervals, --light and --walk on `bench`.
void addBenchAnimationOptions(CLI::App& bench, BenchAnimationOptions& options);

// Exit 0 unless it failed (bad option, a scene without animation, no GL, a file that cannot be written).
int runBenchAnimation(const BenchOptions& bench, const BenchAnimationOptions& options);

}  // namespace shadowlab::cli
