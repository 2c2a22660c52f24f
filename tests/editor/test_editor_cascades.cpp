// Cascades in the editor (issue 20), driven through ImGui input: the Projection panel turns a directional light's
// fit to cascades and sets their count; the frame then has one view per cascade, the map viewer lists each, and the
// "cascades" view tints the picture by the cascade that holds each pixel.
#include "editor_harness.h"

#include <algorithm>
#include <set>

namespace shadowlab::editor::test {

namespace {

int cascadeViews(const FrameStats& stats) {
    return int(std::count_if(stats.views.begin(), stats.views.end(), [](const ShadowViewStats& v) {
        return v.hasView && v.kind == ShadowViewKind::Cascade;
    }));
}

}  // namespace

TEST(EditorCascades, ProjectionPanelTurnsOnCascadesTheViewerListsThemAndTheTintShowsThem) {
    EditorHarness h(testOptions(testFolder("cascades")));
    h.settle();
    ASSERT_TRUE(h.reveal("projection.fit"));
    h.click("projection.fit");
    h.click("projection.fit=cascades");
    h.frame(2);
    EXPECT_EQ(h.state().selected()->projection.fit, ProjectionFit::Cascades);
    EXPECT_EQ(cascadeViews(h.state().stats), 4);
    ASSERT_TRUE(h.reveal("projection.cascadeCount"));
    h.click("projection.cascadeCount");
    h.click("projection.cascadeCount=2");
    h.frame(2);
    ASSERT_EQ(cascadeViews(h.state().stats), 2);

    // The map viewer lists each cascade and shows the one picked.
    ASSERT_TRUE(h.reveal("viewer.view"));
    h.click("viewer.view");
    ASSERT_TRUE(h.hasControl("viewer.view=light 0 cascade:1"));
    h.click("viewer.view=light 0 cascade:1");
    h.frame();
    const ShadowViewStats* shown = h.state().shownView();
    ASSERT_NE(shown, nullptr);
    EXPECT_EQ(shown->kind, ShadowViewKind::Cascade);
    EXPECT_EQ(shown->index, 1);

    // The tint view: the picture changes from lit, and the pixels carry more than one cascade's tint.
    const std::vector<std::uint8_t> lit = h.editor().viewportTarget().readColor();
    h.click("view");
    h.click("view=cascades");
    h.frame(2);
    EXPECT_EQ(h.state().settings.view, ViewMode::Cascades);
    const std::vector<std::uint8_t> tinted = h.editor().viewportTarget().readColor();
    ASSERT_EQ(tinted.size(), lit.size());
    EXPECT_NE(tinted, lit);
    int reddish = 0, greenish = 0;
    for (std::size_t i = 0; i + 3 < tinted.size(); i += 4) {
        const int r = tinted[i], g = tinted[i + 1], b = tinted[i + 2];
        reddish += r > g + 40 && r > b + 40;
        greenish += g > r + 40 && g > b + 40;
    }
    EXPECT_GT(reddish, 100) << "cascade 0's tint is missing";
    EXPECT_GT(greenish, 100) << "cascade 1's tint is missing";
}

}  // namespace shadowlab::editor::test
