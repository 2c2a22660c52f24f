// HARD_CASES 7: shimmering under sub-texel motion. Ortho width 100 at 2048^2 (a texel of 0.0488): the camera moves
// 0.01 (0.2 texel) per frame for 100 frames, then turns 0.1 deg per frame; the light turns by sub-texel steps.
// ShadowLab fits the light's volume to the scene's bounding sphere, not to the view, so under camera motion the map
// must not change at all: no view re-rendered, flicker 0 (texel snapping is for view-fitted volumes; there is none).
// Under light motion the texel grid turns with the light (no snapping can hold it): its flicker is shown beside the
// share of pixels whose V changed, as a figure (the document's "without snapping it is greater than 0").
#include "hardcases/cases.h"

#include "hardcases/hard_case_scenes.h"
#include "scene/builtin_scenes.h"

namespace shadowlab::hardcases {

void runShimmer(CaseContext& context, CaseResult& result) {
    const Scene scene = scaled(*makeBuiltinScene("textbook"), 5.0f);  // a 100 x 100 floor
    Settings s;
    s.lights[0].shadow.resolution = context.pick(2048, 512);
    s.lights[0].shadow.normalOffset = 1.0f;
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    const int frames = context.pick(100, 5);

    // A camera motion must leave the scene-fitted map alone: no view re-rendered, no flicker.
    const auto checkStillMap = [&](MotionKind kind, double step, const std::string& label, const char* picture) {
        Motion motion;
        motion.kind = kind;
        motion.step = step;
        motion.frames = frames + 1;
        const FlickerReport r = context.flicker(scene, s, width, height, motion, picture);
        if (!r.ok) throw std::runtime_error(r.error);
        std::size_t rerendered = 0;
        for (const FlickerPair& pair : r.pairs) rerendered += pair.shadowViewsRendered;
        const std::string steps = kind == MotionKind::Camera ? " (" + figure(r.stepTexels, "texels") + ")" : "";
        result.check(label + steps + " x " + std::to_string(frames) + ": shadow views re-rendered",
                     std::to_string(rerendered), "0 (the map must not change)", rerendered == 0);
        result.check(label + ": flicker, worst pair", percent(r.maxFlickerPercent), "0", r.maxFlickerPercent == 0.0);
    };
    checkStillMap(MotionKind::Camera, 0.01, "camera +0.01", "camera-slide");
    checkStillMap(MotionKind::CameraTurn, 0.1, "camera turned 0.1 deg", "camera-turn");

    Motion light;
    light.kind = MotionKind::Light;
    light.step = 0.05;  // degrees: a corner of the scene's box moves about half a 2048^2 texel per frame
    light.frames = context.pick(20, 4);
    const FlickerReport lit = context.flicker(scene, s, width, height, light, "light-turn");
    if (!lit.ok) throw std::runtime_error(lit.error);
    int above = 0;
    for (const FlickerPair& pair : lit.pairs) above += pair.counts.flickerPercent > pair.counts.vChangedPercent;
    const std::string what = "light turned 0.05 deg (" + figure(lit.stepTexels, "texels") + ")";
    result.info(what + ": flicker vs V changed, mean over " + std::to_string(lit.pairs.size()) + " pairs",
                figure(lit.meanFlickerPercent, "%") + " vs " + figure(lit.meanVChangedPercent, "%") + ", " +
                    std::to_string(above) + " pairs above their own",
                "the map's texel grid turns with the light (nothing to snap): the document expects > 0 here");
}

}  // namespace shadowlab::hardcases
