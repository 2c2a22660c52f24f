#pragma once
// The one timing loop of `bench` and `sweep`: re-render a frame N times with the shadow pass forced, after a few
// warm-up frames, and keep the median of each pass's time (GPU timer queries, or CPU time around glFinish on a
// software rasterizer: FrameStats::timingSource says which).
#include "frame/renderer.h"
#include "timing/repeated_timing.h"

#include <map>
#include <string>
#include <vector>

namespace shadowlab {

struct TimedFrames {
    bool ok = false;
    std::string error;
    double shadowMs = 0.0;        // median over the timed frames
    double mainMs = 0.0;
    double momentsMs = 0.0;       // a moments technique's conversion, blur and mips (0 for depth techniques)
    double blurMs = 0.0;
    double mipsMs = 0.0;          // filter.momentMips's mips pass (0 while it is off)
    double shadowMinMs = 0.0;     // the fastest timed frame: robust to other processes on a loaded CPU
    double mainMinMs = 0.0;
    double wallMsPerFrame = 0.0;
    std::string timingSource;     // "GPU (timer queries)" or "CPU (software rasterizer, ...)"
    FrameStats last;              // the last frame's stats (map size and memory, light space, warnings)
};

// Renders `frames` timed frames of the scene with these settings, each with its shadow pass forced (after the
// warm-up: kGpuWarmUpMs on a GPU).
TimedFrames timeFrames(Renderer& renderer, const Scene& scene, const Settings& settings, const Camera& camera,
                       RenderTarget& target, int frames);

// Every view's own time, frame by frame: `frames` frames with every view forced (after the same warm-up), each
// view's milliseconds by its name (ShadowViewStats::name) and the main pass's. `bench --lights` and
// `bench --planner` read them.
struct PerViewTimes {
    std::string error;                                     // "" unless a frame failed
    std::map<std::string, std::vector<double>> viewMs;     // by view name, one entry per timed frame it ran
    std::vector<double> mainMs;
    FrameStats last;
};
PerViewTimes timeEveryView(Renderer& renderer, const Scene& scene, const Settings& settings, const Camera& camera,
                           RenderTarget& target, int frames);

}  // namespace shadowlab
