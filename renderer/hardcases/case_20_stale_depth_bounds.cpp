// HARD_CASES 20: stale depth bounds and fast camera motion. A camera at eye height faces a wall 3 units away (it sees
// depths 3 to 4), then turns 90 degrees in one frame to look along a floor with posts out to 34 units. With this
// frame's bounds (projection.depthBounds sameFrame) the cascades span what it now sees; with the previous frame's
// they still span the wall's 3..4, so the posts' shadows lie beyond the last cascade and are lit for that frame.
// The bounds are quantized (views/depth_bounds.h): a slow sideways walk keeps the stable fit's cascades, so its
// flicker is 0 with previousFrame bounds.
#include "hardcases/cases.h"

#include "accuracy/stale_depth_bounds.h"
#include "hardcases/hard_case_scenes.h"

namespace shadowlab::hardcases {

namespace {

Scene wallAndPosts() {
    Scene scene = meshKit("wall and posts");
    addFloor(scene, 120.0f);
    addBox(scene, {3.5f, 5.0f, 0.0f}, {1.0f, 10.0f, 30.0f});  // the wall the camera faces first
    for (int i = 1; i <= 4; ++i)
        for (float side : {-1.0f, 1.0f}) addBox(scene, {-1.5f, 2.0f, side * 8.0f * float(i)}, {1.0f, 4.0f, 1.0f});
    return scene;
}

}  // namespace

void runStaleDepthBounds(CaseContext& context, CaseResult& result) {
    const Scene scene = wallAndPosts();
    Settings s;
    LightSettings& sun = s.lights[0];
    sun.type = LightType::Directional;
    sun.direction = {0.4f, -1.0f, 0.25f};
    sun.projection.fit = ProjectionFit::Cascades;
    sun.projection.cascadeFit = CascadeFit::Stable;
    sun.projection.shadowDistance = 60.0f;
    sun.shadow.resolution = context.pick(1024, 512);
    s.camera.autoFrame = false;
    s.camera.position = {0.0, 1.7, 0.0};
    s.camera.target = {1.0, 1.7, 0.0};  // the wall
    if (std::string error = context.applyConvention(s); !error.empty()) throw std::runtime_error(error);
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    const Camera before = cameraFor(s.camera, scene, double(width) / height);

    const StaleBoundsReport r = measureStaleBounds(context.meter(), scene, s, before, 90.0, width, height);
    if (!r.ok) throw std::runtime_error(r.error);
    if (context.picturesOn) {
        context.writePicture("turn-same-frame", width, height, r.sameFrame.report.overlayRgba);
        context.writePicture("turn-previous-frame", width, height, r.previousFrame.report.overlayRgba);
    }
    const auto missing = [](const StaleBoundsFrame& f) {
        return std::to_string(f.missing) + " of " + std::to_string(f.shadowed) + " shadowed (" +
               percent(f.missingPercent) + ")";
    };
    result.check("after a 90 deg turn, bounds of this frame (0 frames late): missing shadows", missing(r.sameFrame),
                 "< 1 % of the shadowed pixels", r.sameFrame.missingPercent < 1.0);
    result.check("after a 90 deg turn, bounds of the frame before (1 frame late): missing shadows",
                 missing(r.previousFrame), "more than 0 frames late (the stale bounds' cost is seen)",
                 r.previousFrame.missing > r.sameFrame.missing);

    // A slow walk sideways with last frame's bounds: the quantized bounds keep the stable fit's cascades.
    Settings walking = s;
    walking.lights[0].projection.depthBounds = DepthBounds::PreviousFrame;
    walking.camera.target = {0.0, 1.7, -1.0};  // along the posts
    Motion walk;
    walk.kind = MotionKind::Camera;
    walk.step = 0.05;
    walk.frames = context.pick(10, 4);
    const FlickerReport f = context.flicker(scene, walking, width, height, walk, "walk");
    if (!f.ok) throw std::runtime_error(f.error);
    // The first frame has no measured depths yet (previousFrame): its cascades span the camera's range and the
    // bounds arrive with frame 1, a change the first pair shows once. The walk is judged from then on.
    double settled = 0.0, first = 0.0;
    for (const FlickerPair& pair : f.pairs)
        (pair.from == 0 ? first : settled) = std::max(pair.from == 0 ? first : settled, pair.counts.flickerPercent);
    result.info("previousFrame bounds: flicker of the first pair (frame 0 had no depths yet)", percent(first),
                "the bounds arrive once");
    result.check("previousFrame bounds, camera +0.05 x " + std::to_string(walk.frames - 1) +
                     ": flicker, worst pair after the first",
                 percent(settled), "0", f.pairs.size() > 1 && settled == 0.0);
}

}  // namespace shadowlab::hardcases
