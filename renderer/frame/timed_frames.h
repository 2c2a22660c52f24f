#pragma once
// The one timing loop of `bench` and `sweep`: re-render a frame N times with the shadow pass forced, after a few
// warm-up frames, and keep the median of each pass's time (GPU timer queries, or CPU time around glFinish on a
// software rasterizer: FrameStats::timingSource says which).
#include "frame/renderer.h"

#include <functional>
#include <string>
#include <vector>

namespace shadowlab {

// Frames rendered and thrown away before timing (shader compiles, first allocations).
inline constexpr int kWarmUpFrames = 3;

// The median (mean of the middle two for an even count); 0 for none.
double medianOf(std::vector<double> values);

// Runs `frame` kWarmUpFrames + frames times; `frame` returns the time(s) of one run in milliseconds, or an error.
// The medians are taken per slot over the timed runs. Shared by the renderer's frames and the bare depth draw.
struct RepeatedTiming {
    std::string error;              // "" unless a run failed
    std::vector<double> medianMs;   // per slot
    std::vector<double> minMs;      // per slot: the least disturbed run (other load only ever adds time)
    double wallMsPerRun = 0.0;      // mean wall time of a timed run (steady clock, blocking on the timings)
};
RepeatedTiming timeRepeated(int frames, const std::function<std::string(std::vector<double>& ms)>& frame);

struct TimedFrames {
    bool ok = false;
    std::string error;
    double shadowMs = 0.0;        // median over the timed frames
    double mainMs = 0.0;
    double shadowMinMs = 0.0;     // the fastest timed frame: robust to other processes on a loaded CPU
    double mainMinMs = 0.0;
    double wallMsPerFrame = 0.0;
    std::string timingSource;     // "GPU (timer queries)" or "CPU (software rasterizer, ...)"
    FrameStats last;              // the last frame's stats (map size and memory, light space, warnings)
};

// Renders `frames` timed frames of the scene with these settings, each with its shadow pass forced.
TimedFrames timeFrames(Renderer& renderer, const Scene& scene, const Settings& settings, const Camera& camera,
                       RenderTarget& target, int frames);

}  // namespace shadowlab
