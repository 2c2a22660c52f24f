// HARD_CASES 7: shimmering under sub-texel motion. Ortho width 100 at 2048^2 (a texel of 0.0488): the camera moves
// 0.01 (0.2 texel) per frame for 100 frames, then turns 0.1 deg per frame. ShadowLab fits the light's volume to the
// scene's bounding sphere, not to the view, so under camera motion the map must not change at all: no view
// re-rendered, the light's matrix bit-equal, flicker 0. (Texel snapping is for view-fitted volumes; there is none.)
#include "hardcases/cases.h"

#include "hardcases/camera_motion.h"
#include "hardcases/hard_case_scenes.h"
#include "scene/builtin_scenes.h"

namespace shadowlab::hardcases {

void runShimmer(CaseContext& context, CaseResult& result) {
    const Scene scene = scaled(*makeBuiltinScene("textbook"), 5.0f);  // a 100 x 100 floor
    Settings s;
    s.lights[0].shadow.resolution = context.pick(2048, 512);
    s.lights[0].shadow.normalOffset = 1.0f;
    s.view = ViewMode::Shadow;
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    const Camera framed = cameraFor(s.camera, scene, double(width) / double(height));
    s.camera.autoFrame = false;
    s.camera.position = framed.position;
    s.camera.target = framed.target;
    const int frames = context.pick(100, 5);
    const CameraMotion slide = moveCamera(context, scene, s, width, height, frames, {0.01, 0.0, 0.0}, 0.0, "slide");
    const CameraMotion turn = moveCamera(context, scene, s, width, height, frames, {0.0, 0.0, 0.0}, 0.1, "turn");
    for (const auto& [name, m] : {std::pair{"camera +0.01 per frame", slide}, std::pair{"camera turned 0.1 deg", turn}}) {
        result.check(std::string(name) + " x " + std::to_string(m.frames) + ": shadow views re-rendered",
                     std::to_string(m.viewsRerendered), "0 (the map must not change)", m.viewsRerendered == 0);
        result.check(std::string(name) + ": light matrix changed", std::to_string(m.lightSpaceChanged) + " frames",
                     "0", m.lightSpaceChanged == 0);
        result.check(std::string(name) + ": the picture moved", std::to_string(m.pictureChanged) + " frames",
                     "> 0 (the camera did move)", m.pictureChanged > 0);
    }
    result.notRun("flicker under camera motion", "0", "needs the flicker measure, renderer/accuracy/flicker.h (issue 14)");
    result.notRun("flicker under sub-texel light motion", "< share of pixels where V changed",
                  "needs the flicker measure, renderer/accuracy/flicker.h (issue 14)");
}

}  // namespace shadowlab::hardcases
