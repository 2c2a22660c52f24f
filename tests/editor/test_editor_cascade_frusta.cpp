// The cascades' frusta in the viewport, the frozen cascades' camera and Stats' row per cascade (issue 20), driven
// through ImGui input: the Projection panel turns the light's fit to cascades, "freeze cascades" keeps them fitted to
// the camera as it was while the view flies out, and the light frustum draws each cascade's box and slice in the
// colour the cascade tint view gives it.
#include "editor_harness.h"

#include "editor/view_rows.h"
#include "image/image_io.h"
#include "shading/cascade_tints.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

namespace shadowlab::editor::test {

namespace {

void turnOnCascades(EditorHarness& h) {
    ASSERT_TRUE(h.reveal("projection.fit"));
    h.click("projection.fit");
    h.click("projection.fit=cascades");
    h.frame(2);
    ASSERT_EQ(h.state().selected()->projection.fit, ProjectionFit::Cascades);
}

std::vector<glm::dmat4> cascadeMatrices(const FrameStats& stats) {
    std::vector<glm::dmat4> m;
    for (const ShadowViewStats& v : stats.views)
        if (v.hasView && v.kind == ShadowViewKind::Cascade) m.push_back(v.space.viewProjection());
    return m;
}

// Pixels of the viewport's picture (RGBA) whose colour is cascade `index`'s tint as 8-bit sRGB-free values: the
// overlay's lines in front of the scene are drawn opaque in exactly that colour.
int tintPixels(const std::vector<std::uint8_t>& rgba, int index) {
    const glm::vec3 t = cascadeTint(index) * 255.0f;
    int n = 0;
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4)
        n += std::abs(int(rgba[i]) - int(std::lround(t.r))) <= 1 && std::abs(int(rgba[i + 1]) - int(std::lround(t.g))) <= 1 &&
             std::abs(int(rgba[i + 2]) - int(std::lround(t.b))) <= 1;
    return n;
}

// The viewport's picture as a PNG under the test output (look at it).
void saveViewport(EditorHarness& h, const std::string& name) {
    const RenderTarget& t = h.editor().viewportTarget();
    std::vector<std::uint8_t> rgba = t.readColor();
    for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    const std::filesystem::path folder = std::filesystem::path(SHADOWLAB_TEST_OUTPUT) / "editor";
    std::filesystem::create_directories(folder);
    EXPECT_EQ(writePng((folder / (name + ".png")).string(), t.width(), t.height(), 4, rgba.data(), true), "");
}

}  // namespace

TEST(EditorCascadeFrusta, FrozenCascadesStayWhileTheViewMovesAndFollowItAgainWhenLetGo) {
    EditorHarness h(testOptions(testFolder("cascade-frusta-freeze")));
    h.settle();
    EXPECT_FALSE(h.hasControl("viewport.freezeCascades")) << "offered for a light without cascades";
    turnOnCascades(h);
    const std::vector<glm::dmat4> fitted = cascadeMatrices(h.state().stats);
    ASSERT_EQ(fitted.size(), 4u);

    h.click("viewport.freezeCascades");
    ASSERT_TRUE(h.state().frozenCascadeCamera.has_value());
    const glm::dvec3 eye = h.editor().orbitCamera()->eye();
    h.drag("viewport.image", 120.0f, 40.0f);
    h.wheel("viewport.image", -4.0f);
    h.frame(2);
    EXPECT_GT(glm::length(h.editor().orbitCamera()->eye() - eye), 0.1) << "the view did not move";
    EXPECT_EQ(cascadeMatrices(h.state().stats), fitted) << "frozen cascades moved with the view";

    h.click("viewport.freezeCascades");
    h.frame(2);
    EXPECT_FALSE(h.state().frozenCascadeCamera.has_value());
    const std::vector<glm::dmat4> following = cascadeMatrices(h.state().stats);
    ASSERT_EQ(following.size(), 4u);
    EXPECT_NE(following, fitted) << "let go, the cascades should fit the moved view";
}

TEST(EditorCascadeFrusta, TheLightFrustumDrawsEachCascadeInItsTintFromOutside) {
    EditorHarness h(testOptions(testFolder("cascade-frusta-tints")), 1280, 720);
    h.settle();
    turnOnCascades(h);
    ASSERT_TRUE(h.state().showLightFrustum);
    // Shadows to 40 units with splits nearer uniform: every cascade then holds part of the scene (by default the
    // shadow distance is the camera's far plane, far beyond it, and the first cascades hold air).
    for (const auto& [key, value] : {std::pair{"projection.shadowDistance", "40"}, {"projection.splitLambda", "0.5"}}) {
        ASSERT_TRUE(h.reveal(key));
        h.ctrlClick(key);
        h.selectAllAndType(value);
    }
    h.frame(2);
    ASSERT_EQ(h.state().selected()->projection.shadowDistance, 40.0f);
    ASSERT_EQ(h.state().selected()->projection.splitLambda, 0.5f);
    // Looking through the fitted camera the slices are the picture's edges: freeze, then fly out to see them.
    h.click("viewport.freezeCascades");
    h.wheel("viewport.image", -7.0f);
    h.drag("viewport.image", 110.0f, 20.0f);
    h.frame(2);
    saveViewport(h, "cascade_frusta");
    const std::vector<std::uint8_t> rgba = h.editor().viewportTarget().readColor();
    for (int c = 0; c < 4; ++c) EXPECT_GT(tintPixels(rgba, c), 150) << "cascade " << c << "'s lines are missing";

    // Without the light frustum none of those lines remain.
    h.click("viewport.frustum");
    h.frame(2);
    const std::vector<std::uint8_t> bare = h.editor().viewportTarget().readColor();
    for (int c = 0; c < 4; ++c) EXPECT_LT(tintPixels(bare, c), 20) << "cascade " << c << "'s colour without lines";
}

TEST(EditorCascadeFrusta, StatsListsEachCascadeWithItsMemoryReasonAndTime) {
    EditorHarness h(testOptions(testFolder("cascade-frusta-stats")), 1280, 720);
    h.settle();
    turnOnCascades(h);
    ASSERT_TRUE(h.reveal("stats.views"));
    h.saveWindow("cascade_stats");  // the rows whole in the narrowest sidebar (look at it)
    for (int c = 0; c < 4; ++c)
        EXPECT_TRUE(h.hasControl("stats.view=light 0 cascade:" + std::to_string(c))) << "no row for cascade " << c;
    EXPECT_FALSE(h.hasControl("stats.view=light 0 cascade:4"));

    // The cascades that drew casters (the far ones may hold none on this small scene: cleared, no time).
    std::set<int> timed;
    for (const ShadowViewStats& v : h.state().stats.views)
        if (v.kind == ShadowViewKind::Cascade && v.ran && v.milliseconds) timed.insert(v.index);
    ASSERT_FALSE(timed.empty()) << "no cascade was drawn";

    // A frame that keeps every cascade (only the overlay changed): each row still shows its layer's memory, why it
    // was kept and, where it was drawn, its newest time.
    h.click("viewport.frustum");
    h.frame(2);
    int cascades = 0;
    for (const ViewRow& row : viewRows(h.state().stats, h.state().viewMilliseconds)) {
        if (row.cascade < 0) continue;
        SCOPED_TRACE(row.name);
        ++cascades;
        const ShadowMap* map = h.editor().renderer().viewMap({0, ShadowViewKind::Cascade, row.cascade});
        ASSERT_NE(map, nullptr);
        EXPECT_EQ(row.memory, memoryText(map->memoryBytes()));
        EXPECT_FALSE(row.ran);
        if (timed.count(row.cascade)) {
            EXPECT_NE(row.milliseconds, "-");
            EXPECT_TRUE(row.timeFromEarlier);
        }
        EXPECT_NE(row.why.find("unchanged"), std::string::npos) << row.why;
    }
    EXPECT_EQ(cascades, 4);
}

}  // namespace shadowlab::editor::test
