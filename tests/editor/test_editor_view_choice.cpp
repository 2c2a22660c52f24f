// The Probe and Export panels' view choice (issue 20), driven through ImGui input: "all views" or one cube face or
// cascade of the selected light, as the CLI's --view; each says which light and view its numbers describe; the
// choice falls back to all views when the light's kind or cascade count changes.
#include "editor_harness.h"

#include <glm/geometric.hpp>
#include <imgui.h>
#include <nlohmann/json.hpp>

namespace shadowlab::editor::test {

namespace {

// The selected light cascaded, its count set through the Projection panel's combo.
void cascades(EditorHarness& h, int count) {
    if (h.state().selected()->projection.fit != ProjectionFit::Cascades) {
        h.click("projection.fit");
        h.click("projection.fit=cascades");
        h.frame(2);
    }
    h.click("projection.cascadeCount");
    h.click("projection.cascadeCount=" + std::to_string(count));
    h.frame(2);
}

// The cascades of the copied JSON snippet's light (cascade indices).
std::vector<int> copiedCascades(EditorHarness& h) {
    h.click("export.copy");
    h.frame();
    const nlohmann::json json = nlohmann::json::parse(ImGui::GetClipboardText());
    std::vector<int> cascades;
    for (const nlohmann::json& light : json.at("lights"))
        for (const nlohmann::json& view : light.at("views")) cascades.push_back(view.value("cascade", -1));
    return cascades;
}

}  // namespace

TEST(EditorViewChoice, TheProbePanelProbesTheChosenViewAndFallsBackToAllViewsWhenTheLightChanges) {
    EditorHarness h(testOptions(testFolder("probe-view")), 1280, 800);
    h.settle();
    cascades(h, 2);
    // Uniform splits over twice the distance to the orbit's target put the seam there, at the middle of the view,
    // and a wide blend band before it, across the floor.
    const Camera eye = h.editor().orbitCamera()->toCamera();
    h.state().edit(h.state().lightKey("projection.splitLambda"), 0.0);
    h.state().edit(h.state().lightKey("projection.shadowDistance"), 2.0 * glm::length(eye.target - eye.position));
    h.state().edit(h.state().lightKey("projection.blendBand"), 0.5);
    h.frame(2);
    // A pixel in the blend band: all views probes both cascades there.
    const ImVec4 view = h.editor().viewportRect();
    const ProbeState& p = h.state().probe;
    int px = -1, py = -1;
    for (int y = int(view.w) - 20; y > 20 && px < 0; y -= int(view.w) / 12) {
        h.clickAt(view.x + view.z / 2 + 0.5f, view.y + float(y) + 0.5f);
        h.frame(2);
        if (p.report && p.report->ok && !p.report->blend.empty()) px = p.report->x, py = p.report->y;
    }
    ASSERT_GE(px, 0) << "no pixel of the centre column lies in the blend band (" << h.saveWindow("probe-view") << ")";
    EXPECT_FALSE(p.report->viewChosen);
    ASSERT_TRUE(h.reveal("probe.describedView"));
    const std::string first = p.report->cascade;
    const std::string other = first == "cascade:0" ? "cascade:1" : "cascade:0";

    // One cascade: the same pixel probed in it alone, the blend partner gone.
    h.click("probe.view");
    ASSERT_TRUE(h.hasControl("probe.view=all views"));
    ASSERT_TRUE(h.hasControl("probe.view=" + other));
    h.click("probe.view=" + other);
    h.frame(2);
    ASSERT_TRUE(p.report && p.report->ok) << (p.report ? p.report->error : "no report");
    EXPECT_EQ(p.report->x, px);
    EXPECT_EQ(p.report->y, py);
    EXPECT_TRUE(p.report->viewChosen);
    EXPECT_EQ(p.report->cascade, other);
    EXPECT_EQ(p.report->viewName, "light 0 " + other);
    EXPECT_TRUE(p.report->blend.empty()) << "a chosen cascade is probed alone";
    h.saveWindow("probe-view-chosen");

    // Three cascades: another set of views, so the choice falls back to all views (never a stale cascade).
    cascades(h, 3);
    EXPECT_TRUE(h.state().probe.view.view.empty());
    ASSERT_TRUE(p.report && p.report->ok);
    EXPECT_FALSE(p.report->viewChosen);
    EXPECT_EQ(p.report->viewCount, 3);

    // A point light: its cube faces, by --view's names.
    h.click("lights.add.point");
    h.frame(2);
    ASSERT_EQ(h.state().selectedLight, 1u);
    h.click("probe.view");
    ASSERT_TRUE(h.hasControl("probe.view=-Y"));
    EXPECT_FALSE(h.hasControl("probe.view=cascade:0"));
    h.click("probe.view=-Y");
    h.frame(2);
    ASSERT_TRUE(p.report && p.report->ok) << (p.report ? p.report->error : "no report");
    EXPECT_EQ(p.report->light, 1u);
    EXPECT_EQ(p.report->face, 3);
    EXPECT_TRUE(p.report->viewChosen);
    // The light's kind changes: one view, nothing to choose.
    h.click("light.type");
    h.click("light.type=spot");
    h.frame(2);
    EXPECT_TRUE(h.state().probe.view.view.empty());
    ASSERT_TRUE(p.report && p.report->ok) << p.report->error;
    EXPECT_EQ(p.report->viewCount, 1);
    EXPECT_FALSE(p.report->viewChosen);
    EXPECT_FALSE(h.hasControl("probe.view")) << "a one-view light shows no choice";
}

TEST(EditorViewChoice, TheExportPanelExportsTheChosenCascadeAlone) {
    EditorHarness h(testOptions(testFolder("export-view")), 1280, 800);
    h.settle();
    cascades(h, 4);
    h.click("export.format");
    h.click("export.format=json");
    h.frame();
    EXPECT_EQ(copiedCascades(h), (std::vector<int>{0, 1, 2, 3})) << "all views: the cascaded light whole";
    h.click("export.view");
    h.click("export.view=cascade:2");
    h.frame();
    EXPECT_EQ(copiedCascades(h), (std::vector<int>{2}));
    EXPECT_NE(h.state().messages.back().text.find("light 0 cascade:2"), std::string::npos)
        << h.state().messages.back().text;
    // Two cascades: cascade:2 no longer exists, the panel exports the light whole again.
    cascades(h, 2);
    EXPECT_EQ(copiedCascades(h), (std::vector<int>{0, 1}));
    // Every light: views are a light's, so the choice is off.
    h.click("export.light");
    h.click("export.light=all");
    h.frame();
    EXPECT_EQ(copiedCascades(h), (std::vector<int>{0, 1}));
}

}  // namespace shadowlab::editor::test
