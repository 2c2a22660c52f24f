#pragma once
// `sweep --play K`: a point evaluated where its shadow.update matters (issue 22). A sweep point's maps are otherwise
// drawn once and timed with every view forced, so every policy costs and reads the same. Played, the point's scene
// advances K frames of `step` seconds from its animation.time (frame f at time + f x step) through a renderer of the
// point's own: frame 0 draws every view (the cache fills), then the point's policy decides what each frame redraws,
// and frame K-1 is measured against the exact reference at its time. For everyNthFrame with N dividing K (--play 8
// and N = 2, 4, 8) frame K-1 is the last before an update: N-1 frames of motion stale, the most the
// policy lets a map lag. The shadow ms is the mean of frames 1..K-1 as drawn (not forced): what the policy costs
// per frame while the scene moves, everyNthFrame's update frames spread over the frames between (wall ms per frame: frames 0..K-2, the last is mostly the measurement). Needs a
// current GL 4.5 context.
#include "accuracy/accuracy_meter.h"
#include "frame/timed_frames.h"

#include <string>

namespace shadowlab {

struct PlayedPoint {
    std::string error;          // "" unless a frame failed or the animation cannot play
    TimedFrames timed;          // means over frames 1..K-1 as drawn (min: the fastest); .last = frame K-1's stats
    AccuracyReport report;      // frame K-1 against the reference at its time
    double measuredTime = 0.0;  // animation.time of frame K-1
    double viewsRenderedPerFrame = 0.0;  // frames 1..K-1
};

// `played`: a copy of the scene, posed here at each frame's time; the caller keeps it alive as long as the meter (the
// meter caches its reference by the scene it measured). `settings` must hold the one light the meter measures (as
// every sweep point does). The meter draws the played frames through its tool-renderer hook and is left with its
// own renderer again.
PlayedPoint playPoint(AccuracyMeter& meter, Scene& played, const Settings& settings, const Camera& camera, int width,
                      int height, int frames, double step, AccuracyProgress* progress = nullptr);

}  // namespace shadowlab
