// The depth-bounds fit on the GPU (frame/depth_bounds_pass.cpp): the seen depths tighten the splits against the fit
// off, sameFrame measures this frame's view, previousFrame the frame before (one frame late), and the pass is
// timed in the frame's stats.
#include "gl_fixture.h"

#include "settings/settings_fields.h"

namespace shadowlab::test {
namespace {

class DepthBoundsGl : public GlTest {};

// The textbook from x = 0, y = 1, z = 4: `towardCube` looks at the cube (depths about 3 to 14, the floor behind it),
// else away along +z (the floor from about 2.4 to its edge at 6).
Settings looking(bool towardCube, const char* bounds) {
    Settings s = loadShippedPreset("default");
    EXPECT_EQ(applySettingOverride(s, "lights.0.projection.fit=cascades"), "");
    EXPECT_EQ(applySettingOverride(s, std::string("lights.0.projection.depthBounds=") + bounds), "");
    s.camera.autoFrame = false;
    s.camera.position = {0.0, 1.0, 4.0};
    s.camera.target = towardCube ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 1.0, 8.0);
    return s;
}

constexpr int kWidth = 160, kHeight = 90;

const ShadowViewStats& cascade(const FrameStats& stats, int index) {
    for (const ShadowViewStats& v : stats.views)
        if (v.hasView && v.kind == ShadowViewKind::Cascade && v.index == index) return v;
    throw std::runtime_error("no cascade " + std::to_string(index));
}

// The cascade whose slice holds a depth (the last one beyond).
const ShadowViewStats& holding(const FrameStats& stats, double depth) {
    for (int i = 0; i < 3; ++i)
        if (cascade(stats, i).slice.farDepth >= depth) return cascade(stats, i);
    return cascade(stats, 3);
}

void expectSameDepths(const std::optional<ViewDepths>& a, const std::optional<ViewDepths>& b, const char* what) {
    ASSERT_TRUE(a && b) << what;
    EXPECT_NEAR(a->nearest, b->nearest, 1e-3 * b->nearest) << what;
    EXPECT_NEAR(a->farthest, b->farthest, 1e-3 * b->farthest) << what;
}

TEST_F(DepthBoundsGl, TheSeenDepthsTightenTheSplits) {
    const Scene scene = loadBuiltin("textbook");
    Renderer renderer;
    const View off = renderView(renderer, scene, looking(true, "off"), kWidth, kHeight);
    const View on = renderView(renderer, scene, looking(true, "sameFrame"), kWidth, kHeight);
    ASSERT_TRUE(off.stats.ok && on.stats.ok) << off.stats.error << on.stats.error;
    EXPECT_FALSE(off.stats.depthBoundsPass.ran);
    EXPECT_FALSE(off.stats.seenDepths);
    ASSERT_TRUE(on.stats.seenDepths);
    const ViewDepths seen = *on.stats.seenDepths;
    EXPECT_GT(seen.nearest, 2.3);   // the floor in front of the cube, from 1 / tan(22.5 deg) = 2.41 on
    EXPECT_LT(seen.nearest, 3.01);
    EXPECT_GT(seen.farthest, 10.0);  // the floor behind the cube
    EXPECT_LT(seen.farthest, 20.0);
    EXPECT_TRUE(on.stats.depthBoundsPass.ran);
    EXPECT_TRUE(on.stats.depthBoundsPass.milliseconds) << "the pass is timed";
    // Without the fit the first cascade ends before anything is seen (the camera's near plane is tiny: empty air)
    // and the last reaches the camera's far plane; with it the first split lies among the seen depths and the last
    // cascade ends at the farthest of them.
    const double offSplit = cascade(off.stats, 0).slice.farDepth, onSplit = cascade(on.stats, 0).slice.farDepth;
    EXPECT_LT(offSplit, seen.nearest);
    EXPECT_GT(onSplit, seen.nearest);
    EXPECT_LT(onSplit, seen.farthest);
    EXPECT_GE(cascade(on.stats, 3).slice.farDepth, seen.farthest);
    EXPECT_LT(cascade(on.stats, 3).slice.farDepth, cascade(off.stats, 3).slice.farDepth);  // 13.5 against 19.2
    // The far cascades' texels are finer (at the nearest seen depth the logarithmic split of the fit-off scheme,
    // which spends two cascades on 0.07..2.5, happens to be finer still: the fit evens the texels out).
    EXPECT_LT(holding(on.stats, seen.farthest).space.texelWorldSize,
              holding(off.stats, seen.farthest).space.texelWorldSize);
    // The views say why they re-rendered.
    EXPECT_EQ(cascade(on.stats, 0).reason, "projection.depthBounds changed");
}

TEST_F(DepthBoundsGl, PreviousFrameIsOneFrameLate) {
    const Scene scene = loadBuiltin("textbook");
    Renderer now;  // sameFrame: what each view sees
    const std::optional<ViewDepths> cube =
        renderView(now, scene, looking(true, "sameFrame"), kWidth, kHeight).stats.seenDepths;
    const std::optional<ViewDepths> away =
        renderView(now, scene, looking(false, "sameFrame"), kWidth, kHeight).stats.seenDepths;
    ASSERT_TRUE(cube && away);
    ASSERT_GT(cube->farthest, 1.5 * away->farthest) << "the two views must see different depths";

    Renderer late;
    const View first = renderView(late, scene, looking(true, "previousFrame"), kWidth, kHeight);
    EXPECT_FALSE(first.stats.seenDepths) << "no frame before the first";
    EXPECT_NE(std::find_if(first.stats.warnings.begin(), first.stats.warnings.end(),
                           [](const std::string& w) { return w.find("projection.depthBounds: no depths measured") == 0; }),
              first.stats.warnings.end());
    expectSameDepths(renderView(late, scene, looking(true, "previousFrame"), kWidth, kHeight).stats.seenDepths, cube,
                     "the second frame has the first's depths");
    const View turned = renderView(late, scene, looking(false, "previousFrame"), kWidth, kHeight);
    expectSameDepths(turned.stats.seenDepths, cube, "the frame after the turn has the depths from before it");
    EXPECT_TRUE(turned.stats.depthBoundsPass.ran);
    expectSameDepths(renderView(late, scene, looking(false, "previousFrame"), kWidth, kHeight).stats.seenDepths, away,
                     "one frame later it has its own");
}

}  // namespace
}  // namespace shadowlab::test
