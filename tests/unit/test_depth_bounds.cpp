// The depth-bounds fit (views/depth_bounds.cpp): splits over the seen depths, the log-space quantization (stable
// under small changes), the fall-back when nothing is seen, window depth back to view depth, the planner's reason.
// No GL.
#include "views/cascade_views.h"
#include "views/depth_bounds.h"
#include "views/shadow_planner.h"
#include "views/view_builders.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace shadowlab;

namespace {

LightSettings sun(DepthBounds bounds) {
    LightSettings l;
    l.direction = {-0.5f, -1.0f, -0.3f};
    l.shadow.resolution = 1024;
    l.projection.fit = ProjectionFit::Cascades;
    l.projection.depthBounds = bounds;
    l.projection.shadowDistance = 500.0f;
    return l;
}

ViewCamera camera(std::optional<ViewDepths> seen) {
    ViewCamera c;
    c.eye = {0.0, 1.7, 0.0};
    c.forward = {0.0, 0.0, -1.0};
    c.right = {1.0, 0.0, 0.0};
    c.up = {0.0, 1.0, 0.0};
    c.tanHalfFovY = std::tan(glm::radians(25.0));
    c.aspect = 16.0 / 9.0;
    c.nearPlane = 0.1;
    c.farPlane = 1000.0;
    c.seenDepths = seen;
    return c;
}

std::vector<ShadowView> viewsOf(const LightSettings& light, const ViewCamera& c) {
    Bounds b;
    b.extend(glm::vec3(-200.0f, 0.0f, -200.0f));
    b.extend(glm::vec3(200.0f, 30.0f, 200.0f));
    std::string error;
    const auto views = buildLightViews(light, 0, b, glm::dvec3(0.0), &c, error);
    EXPECT_TRUE(views) << error;
    return views ? *views : std::vector<ShadowView>{};
}

}  // namespace

TEST(DepthBounds, SplitsSpanTheSeenDepthsOnTheGrid) {
    const ViewCamera c = camera(ViewDepths{5.0, 40.0});
    const std::vector<ShadowView> off = viewsOf(sun(DepthBounds::Off), c);
    const std::vector<ShadowView> on = viewsOf(sun(DepthBounds::SameFrame), c);
    ASSERT_EQ(off.size(), 4u);
    ASSERT_EQ(on.size(), 4u);
    // Over [camera near, shadow distance] without the fit; over the seen depths rounded out to the grid with it.
    EXPECT_DOUBLE_EQ(off.back().slice.farDepth, 500.0);
    EXPECT_DOUBLE_EQ(on.front().slice.fitNear, depthGridDown(5.0));
    EXPECT_DOUBLE_EQ(on.back().slice.farDepth, depthGridUp(40.0));
    EXPECT_LT(depthGridDown(5.0), 5.0);
    EXPECT_GT(depthGridUp(40.0), 40.0);
    // The first split comes much nearer: its texels are spent where things are.
    EXPECT_LT(on.front().slice.farDepth, 0.5 * off.front().slice.farDepth);  // 10.0 against 31.9
    EXPECT_LT(on.front().space.texelWorldSize, 0.5 * off.front().space.texelWorldSize);
}

TEST(DepthBounds, TheGridIsStableUnderSmallChanges) {
    for (double d : {0.3, 1.0, 5.0, 40.0, 700.0, 12345.0}) {
        EXPECT_LE(depthGridDown(d), d);
        EXPECT_GE(depthGridUp(d), d);
        EXPECT_LE(depthGridUp(d) / depthGridDown(d), std::exp2(1.0 / kDepthBoundsStepsPerOctave) * (1.0 + 1e-12));
    }
    // Seen depths that move by about 1 % (off the grid's steps) give the very same cascades.
    const LightSettings light = sun(DepthBounds::PreviousFrame);
    const std::vector<ShadowView> a = viewsOf(light, camera(ViewDepths{5.0, 40.0}));
    const std::vector<ShadowView> b = viewsOf(light, camera(ViewDepths{5.05, 40.4}));
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].slice.farDepth, b[i].slice.farDepth);
        EXPECT_EQ(a[i].space.orthoSize, b[i].space.orthoSize) << "cascade " << i << " changed its size";
    }
    // Across a step, it changes.
    const std::vector<ShadowView> far = viewsOf(light, camera(ViewDepths{5.0, 60.0}));
    EXPECT_GT(far.back().slice.farDepth, a.back().slice.farDepth);
}

TEST(DepthBounds, NothingSeenFallsBackWithAMessage) {
    const LightSettings light = sun(DepthBounds::SameFrame);
    const std::vector<ShadowView> off = viewsOf(sun(DepthBounds::Off), camera(std::nullopt));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const std::optional<ViewDepths>& seen :
         {std::optional<ViewDepths>{}, std::optional<ViewDepths>{ViewDepths{1.0, 0.0}},
          std::optional<ViewDepths>{ViewDepths{nan, nan}}, std::optional<ViewDepths>{ViewDepths{600.0, 900.0}},
          std::optional<ViewDepths>{ViewDepths{0.01, 0.05}}}) {
        const ViewCamera c = camera(seen);
        std::string fallback;
        EXPECT_FALSE(cascadeDepthBounds(light, c, &fallback));
        EXPECT_NE(fallback.find("projection.depthBounds: "), std::string::npos);
        EXPECT_NE(fallback.find("the shadow distance (500"), std::string::npos) << fallback;
        const std::vector<ShadowView> views = viewsOf(light, c);
        ASSERT_EQ(views.size(), off.size());
        for (std::size_t i = 0; i < views.size(); ++i) {
            EXPECT_TRUE(std::isfinite(views[i].slice.farDepth));
            EXPECT_EQ(views[i].slice.farDepth, off[i].slice.farDepth);
            EXPECT_EQ(views[i].space.viewProjection(), off[i].space.viewProjection());
        }
    }
    std::string message;
    cascadeDepthBounds(light, camera(ViewDepths{1.0, 0.0}), &message);
    EXPECT_NE(message.find("sees nothing"), std::string::npos) << message;
    // Off, or manual splits: no bounds.
    EXPECT_FALSE(cascadeDepthBounds(sun(DepthBounds::Off), camera(ViewDepths{5.0, 40.0})));
    LightSettings manual = light;
    manual.projection.splits = {10.0f, 50.0f, 100.0f};
    EXPECT_FALSE(cascadeDepthBounds(manual, camera(ViewDepths{5.0, 40.0})));
}

TEST(DepthBounds, WindowDepthBackToViewDepth) {
    const glm::dmat4 perspective = glm::perspective(glm::radians(50.0), 16.0 / 9.0, 0.1, 1000.0);
    const glm::dmat4 ortho = glm::ortho(-8.0, 8.0, -4.5, 4.5, 0.5, 300.0);
    for (const glm::dmat4& p : {perspective, ortho})
        for (double z : {0.5, 1.0, 7.0, 123.0, 299.0}) {
            const glm::dvec4 clip = p * glm::dvec4(0.3, -0.2, -z, 1.0);
            const double window = 0.5 * clip.z / clip.w + 0.5;
            EXPECT_NEAR(viewDepthOfWindowDepth(p, window), z, 1e-6 * z);
        }
}

TEST(DepthBounds, TheFrameMeasuresWhatItsLightsAsk) {
    Settings s;
    s.lights[0] = sun(DepthBounds::Off);
    EXPECT_EQ(depthBoundsWanted(s), DepthBounds::Off);
    s.lights.push_back(sun(DepthBounds::PreviousFrame));
    EXPECT_EQ(depthBoundsWanted(s), DepthBounds::PreviousFrame);
    s.lights.push_back(sun(DepthBounds::SameFrame));
    EXPECT_EQ(depthBoundsWanted(s), DepthBounds::SameFrame);
    s.lights[2].projection.fit = ProjectionFit::Scene;  // only cascaded lights count
    EXPECT_EQ(depthBoundsWanted(s), DepthBounds::PreviousFrame);
}

// Hysteresis: what is seen drifting back and forth across a grid line keeps the same bounds; leaving them, or
// bounds grown twice too loose, moves them (snapped outward to the grid).
TEST(DepthBounds, KeptBoundsChangeOnlyWhenWhatIsSeenLeavesThemOrTheyGrowTooLoose) {
    EXPECT_FALSE(keptDepthBounds(std::nullopt, std::nullopt));
    const std::optional<ViewDepths> first = keptDepthBounds(std::nullopt, ViewDepths{3.0, 30.0});
    ASSERT_TRUE(first);
    EXPECT_LE(first->nearest, 3.0);
    EXPECT_GE(first->farthest, 30.0);
    EXPECT_DOUBLE_EQ(first->nearest, depthGridDown(3.0));
    EXPECT_DOUBLE_EQ(first->farthest, depthGridUp(30.0));
    // A slow walk: the seen depths wander by a few percent around a grid line (2^(19/4) = 26.9 lies in 25..31).
    std::optional<ViewDepths> kept = first;
    for (int i = 0; i < 100; ++i) {
        const double wobble = 1.0 + 0.03 * std::sin(0.7 * i);
        kept = keptDepthBounds(kept, ViewDepths{3.0 * wobble * 1.02, 26.9 * wobble});
        EXPECT_EQ(*kept, *first) << "frame " << i;
    }
    // Something seen beyond the far bound: it follows at once (a stale far bound loses shadows).
    const std::optional<ViewDepths> farther = keptDepthBounds(kept, ViewDepths{3.0, 40.0});
    EXPECT_GE(farther->farthest, 40.0);
    // The near bound only places the splits: a little nearer keeps it, twice as near moves it.
    EXPECT_EQ(*keptDepthBounds(kept, ViewDepths{2.0, 30.0}), *first);
    const std::optional<ViewDepths> nearer = keptDepthBounds(kept, ViewDepths{1.0, 30.0});
    EXPECT_LE(nearer->nearest, 1.0);
    // Twice too loose: they tighten.
    const std::optional<ViewDepths> tighter = keptDepthBounds(kept, ViewDepths{3.0, 10.0});
    EXPECT_LT(tighter->farthest, 15.0);
    EXPECT_GE(tighter->farthest, 10.0);
}
