#include "accuracy/stale_depth_bounds.h"

#include "accuracy/motion.h"
#include "reference/visibility.h"

namespace shadowlab {

StaleBoundsReport measureStaleBounds(AccuracyMeter& meter, const Scene& scene, const Settings& settings,
                                     const Camera& before, double turnDegrees, int width, int height) {
    StaleBoundsReport out;
    out.turnDegrees = turnDegrees;
    if (settings.lights.empty() || settings.lights[0].type != LightType::Directional ||
        settings.lights[0].projection.fit != ProjectionFit::Cascades) {
        out.error = "lights.0: the stale-bounds measure needs a directional light with projection.fit cascades";
        return out;
    }
    Motion turn;
    turn.kind = MotionKind::CameraTurn;
    turn.step = turnDegrees;
    const Camera after = cameraAtFrame(before, turn, 1);
    for (StaleBoundsFrame* frame : {&out.sameFrame, &out.previousFrame}) {
        frame->latency = frame == &out.sameFrame ? DepthBounds::SameFrame : DepthBounds::PreviousFrame;
        Settings s = settings;
        s.lights[0].projection.depthBounds = frame->latency;
        // Two frames before the turn: the second has the first's bounds, whatever the meter drew before.
        for (const Camera* camera : {&before, &before, &after}) {
            frame->report = meter.measure(scene, s, *camera, width, height);
            if (!frame->report.ok) {
                out.error = "stale depth bounds (" + std::string(camera == &after ? "after" : "before") +
                            " the turn): " + frame->report.error;
                return out;
            }
        }
        const AccuracyReport& r = frame->report;
        for (std::size_t i = 0; i < r.pixelClass.size(); ++i) {
            if (!r.pixelMeasured[i] || r.pixelClass[i] != PixelClass::Shadowed) continue;
            ++frame->shadowed;
            frame->missing += r.pixelShadow[i] >= 0.5f;
        }
        frame->missingPercent = frame->shadowed ? 100.0 * double(frame->missing) / double(frame->shadowed) : 0.0;
    }
    out.ok = true;
    return out;
}

}  // namespace shadowlab
