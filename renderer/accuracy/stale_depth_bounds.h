#pragma once
// What stale depth bounds cost (HARD_CASES 20): the frame right after a fast camera turn, measured against the exact
// reference with the bounds of this frame (projection.depthBounds sameFrame) and of the frame before the turn
// (previousFrame). With the previous frame's bounds the cascades span what the camera saw before it turned: receivers
// beyond them are past the last cascade (lit) for one frame. The count is the missing shadows: pixels the reference
// shadows (V = 0) that the picture shows lit (S >= 0.5).
#include "accuracy/accuracy_meter.h"
#include "frame/camera.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <cstddef>
#include <string>

namespace shadowlab {

struct StaleBoundsFrame {
    DepthBounds latency = DepthBounds::SameFrame;
    std::size_t shadowed = 0;  // measured pixels with V = 0
    std::size_t missing = 0;   // of those, shown lit (S >= 0.5)
    double missingPercent = 0.0;  // missing / shadowed * 100
    AccuracyReport report;        // the frame after the turn
};

struct StaleBoundsReport {
    bool ok = false;
    std::string error;  // names the key or the measurement that failed
    double turnDegrees = 0.0;
    StaleBoundsFrame sameFrame, previousFrame;
};

// Light 0 must be a directional light with projection.fit cascades. `before`: the camera before the turn; it turns
// `turnDegrees` about world up (the flicker measure's camera turn, motion.h) in one frame. Each latency is measured
// on its own history: two frames at `before` (the bounds settle), then the turned frame.
StaleBoundsReport measureStaleBounds(AccuracyMeter& meter, const Scene& scene, const Settings& settings,
                                     const Camera& before, double turnDegrees, int width, int height);

}  // namespace shadowlab
