#pragma once
// The repeated-run timing loop under `bench`, `sweep` and the bare depth draw: a warm-up thrown away, then the
// median and the minimum of each timed slot. No GL here (unit-tested with fake frames).
#include <functional>
#include <string>
#include <vector>

namespace shadowlab {

// Frames rendered and thrown away before timing (shader compiles, first allocations).
inline constexpr int kWarmUpFrames = 3;
// On a GPU the warm-up also lasts this long: a GPU raises its clocks only after some load (the first sweep point
// read 3.16 ms where the same configuration measured later read 2.0 ms, lent H100). Not on a software rasterizer,
// whose frames are slow enough that kWarmUpFrames already take longer.
inline constexpr double kGpuWarmUpMs = 300.0;
inline constexpr int kMaxWarmUpFrames = 1000;

// Counts the warm-up: `running()` before each frame says whether that frame is still thrown away.
class WarmUp {
public:
    explicit WarmUp(double minimumMs);
    bool running();

private:
    int frames_ = 0;
    double minimumMs_;
    double startMs_ = -1.0;
};

// The median (mean of the middle two for an even count); 0 for none.
double medianOf(std::vector<double> values);

// Runs `frame` through the warm-up (kWarmUpFrames and at least warmUpMs), then `frames` times; `frame` returns the
// time(s) of one run in milliseconds, or an error. The medians are taken per slot over the timed runs. Shared by the
// renderer's frames and the bare depth draw.
struct RepeatedTiming {
    std::string error;              // "" unless a run failed
    std::vector<double> medianMs;   // per slot
    std::vector<double> minMs;      // per slot: the least disturbed run (other load only ever adds time)
    double wallMsPerRun = 0.0;      // mean wall time of a timed run (steady clock, blocking on the timings)
    int warmUpRuns = 0;             // runs thrown away
};
RepeatedTiming timeRepeated(int frames, const std::function<std::string(std::vector<double>& ms)>& frame,
                            double warmUpMs = 0.0);

}  // namespace shadowlab
