// Issue 13, "Why this pixel" in the editor: a click on a viewport pixel (or P held over one) fills the Probe panel
// with that pixel's taps, bias terms and S (CPU and GPU agreeing); the Shadow map viewer outlines the taps; an edit
// probes the same pixel again; a measurement of the same view adds the exact verdict.
#include "editor_harness.h"


namespace shadowlab::editor::test {

namespace {

class EditorProbe : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
        harness = std::make_unique<EditorHarness>(testOptions(folder), 1280, 800);
        harness->settle();
    }
    // The window pixel of a viewport pixel.
    ImVec2 windowPoint(int x, int y) const {
        const ImVec4 view = harness->editor().viewportRect();
        return ImVec2(view.x + float(x) + 0.5f, view.y + float(y) + 0.5f);
    }
    std::filesystem::path folder;
    std::unique_ptr<EditorHarness> harness;
};

bool nearColour(const std::uint8_t* p, int r, int g, int b) {
    return std::abs(p[0] - r) < 40 && std::abs(p[1] - g) < 40 && std::abs(p[2] - b) < 40;
}

}  // namespace

TEST_F(EditorProbe, ClickingAPixelExplainsItAndTheViewerOutlinesItsTaps) {
    EditorHarness& h = *harness;
    EXPECT_TRUE(h.reveal("probe.hint")) << "the Probe panel says how to use it before the first probe";
    const ImVec4 view = h.editor().viewportRect();
    const int px = int(view.z / 2), py = int(view.w / 2);
    const ImVec2 at = windowPoint(px, py);
    h.clickAt(at.x, at.y);
    h.frame(2);
    const ProbeState& p = h.state().probe;
    ASSERT_TRUE(p.report.has_value()) << "a click on the viewport probes its pixel";
    ASSERT_TRUE(p.report->ok) << p.report->error;
    EXPECT_EQ(p.report->x, px);
    EXPECT_EQ(p.report->y, py);
    EXPECT_TRUE(p.report->agrees) << p.report->shadowCpu << " vs GPU " << p.report->shadowGpu;
    EXPECT_EQ(p.report->taps.size(), 9u) << "the default preset's PCF 3x3";
    EXPECT_TRUE(h.reveal("probe.summary"));
    EXPECT_TRUE(h.reveal("probe.lines"));
    EXPECT_FALSE(h.hasControl("probe.hint"));

    // The viewer: zoom to the probe, the lookup's yellow cross and the taps' outlines are drawn over the map.
    h.click("viewer.zoomToProbe");
    h.frame(3);
    EXPECT_GT(h.state().viewer.zoomPan.zoom(), 10.0);
    ASSERT_TRUE(h.reveal("viewer.probeLookup"));
    const ControlRect cross = h.rect("viewer.probeLookup");
    const ControlRect image = h.rect("viewer.image");
    EXPECT_GT(cross.centerX(), image.x);
    EXPECT_LT(cross.centerX(), image.x + image.w);
    EXPECT_GT(cross.centerY(), image.y);
    EXPECT_LT(cross.centerY(), image.y + image.h);
    const std::vector<std::uint8_t> window = h.readWindow();
    int yellow = 0, outline = 0;
    for (int y = int(cross.centerY()) - 60; y <= int(cross.centerY()) + 60; ++y)
        for (int x = int(cross.centerX()) - 60; x <= int(cross.centerX()) + 60; ++x) {
            if (x < 0 || y < 0 || x >= h.width() || y >= h.height()) continue;
            const std::uint8_t* c = &window[(std::size_t(y) * std::size_t(h.width()) + std::size_t(x)) * 4];
            yellow += nearColour(c, 255, 230, 0);
            outline += nearColour(c, 60, 220, 80) || nearColour(c, 240, 50, 50);
        }
    EXPECT_GT(yellow, 8) << "the lookup's cross (" << h.saveWindow("probe-viewer") << ")";
    EXPECT_GT(outline, 40) << "the taps' outlines (" << h.saveWindow("probe-viewer") << ")";
    h.saveWindow("probe-editor");

    // An edit probes the same pixel again: zero bias shows in the bias terms.
    h.state().edit("shadow.depthBias", 0.0);
    h.state().edit("shadow.slopeScaledDepthBias", 0.0);
    h.frame(3);
    ASSERT_TRUE(p.report && p.report->ok);
    EXPECT_EQ(p.report->x, px);
    EXPECT_DOUBLE_EQ(p.report->bias.total.depth, 0.0);
    EXPECT_TRUE(p.report->agrees);
}

TEST_F(EditorProbe, HoldingPProbesUnderTheCursorAndADragDoesNot) {
    EditorHarness& h = *harness;
    const ImVec4 view = h.editor().viewportRect();
    const ImVec2 a = windowPoint(int(view.z / 2) - 30, int(view.w / 2) + 10);
    h.moveMouse(a.x, a.y);
    h.setKey(keys::kP, true);
    h.frame(3);
    ASSERT_TRUE(h.state().probe.report.has_value());
    EXPECT_EQ(h.state().probe.report->x, int(view.z / 2) - 30);
    const ImVec2 b = windowPoint(int(view.z / 2) + 25, int(view.w / 2) - 5);
    h.moveMouse(b.x, b.y);
    h.frame(3);
    EXPECT_EQ(h.state().probe.report->x, int(view.z / 2) + 25);
    EXPECT_EQ(h.state().probe.report->y, int(view.w / 2) - 5);
    h.setKey(keys::kP, false);
    h.frame();
    // An orbit drag ends on another pixel, but asks for no probe of it (it re-probes the same pixel in the new view).
    h.drag("viewport.image", 80.0f, 0.0f);
    h.frame(2);
    EXPECT_EQ(h.state().probe.report->x, int(view.z / 2) + 25);
    // The background: refused, with the reason in the panel.
    h.clickAt(view.x + 2.0f, view.y + 2.0f);
    h.frame(2);
    ASSERT_TRUE(h.state().probe.report.has_value());
    EXPECT_FALSE(h.state().probe.report->ok);
    EXPECT_NE(h.state().probe.report->error.find("background"), std::string::npos) << h.state().probe.report->error;
    EXPECT_TRUE(h.reveal("probe.summary"));
}

TEST_F(EditorProbe, AMeasurementOfTheSameViewAddsTheExactVerdict) {
    EditorHarness& h = *harness;
    h.click("accuracy.measure");
    h.waitForAccuracyJob();
    ASSERT_TRUE(h.state().accuracy.report.has_value());
    const ImVec4 view = h.editor().viewportRect();
    const ImVec2 at = windowPoint(int(view.z / 2), int(view.w / 2));
    h.clickAt(at.x, at.y);
    h.frame(2);
    const ProbeState& p = h.state().probe;
    ASSERT_TRUE(p.report && p.report->ok) << (p.report ? p.report->error : "no report");
    EXPECT_TRUE(p.withMeasurement);
    EXPECT_TRUE(p.report->measured);
    EXPECT_NEAR(p.report->measuredShadow, p.report->shadowGpu, 1e-6) << "the measured frame is the probed one";
}

TEST_F(EditorProbe, CtrlDragDrawsALineWhoseDepthProfileThePanelPlots) {
    // The depth profile in the editor: Ctrl+drag across the viewport draws a line without orbiting the camera; the
    // Probe panel then plots the profile along it; zero bias puts acne on the floor's samples, an edit re-profiles.
    EditorHarness& h = *harness;
    const glm::dvec3 eyeBefore = h.editor().orbitCamera()->toCamera().position;
    const ImVec4 view = h.editor().viewportRect();
    const int x0 = int(view.z / 2) - 40, y0 = int(view.w / 2) + 60;
    const ImVec2 a = windowPoint(x0, y0);
    h.setKey(keys::kLeftControl, true);
    h.moveMouse(a.x, a.y);
    ImGui::GetIO().MouseDown[0] = true;
    h.frame();
    for (int i = 1; i <= 8; ++i) h.moveMouse(a.x + 10.0f * float(i), a.y);
    ASSERT_TRUE(h.state().probe.drawingLine) << "the drag draws a line while it lasts";
    ImGui::GetIO().MouseDown[0] = false;
    h.frame(3);
    h.setKey(keys::kLeftControl, false);
    h.frame();
    const glm::dvec3 eyeAfter = h.editor().orbitCamera()->toCamera().position;
    EXPECT_EQ(eyeBefore, eyeAfter) << "a Ctrl+drag does not orbit";
    const ProbeState& p = h.state().probe;
    ASSERT_TRUE(p.profile.has_value()) << "releasing the drag profiles the line";
    ASSERT_TRUE(p.profile->ok) << p.profile->error;
    EXPECT_EQ(p.profile->from, glm::ivec2(x0, y0));
    EXPECT_EQ(p.profile->to, glm::ivec2(x0 + 80, y0));
    EXPECT_EQ(p.profile->samples.size(), 81u);
    EXPECT_GT(p.profile->surfaces, 40) << "the line crosses the scene";
    EXPECT_EQ(p.profile->acne, 0) << "the default preset";
    EXPECT_TRUE(h.reveal("probe.profile"));
    EXPECT_TRUE(h.reveal("probe.profilePlot"));
    EXPECT_FALSE(p.report.has_value()) << "the drag probed no pixel";
    h.saveWindow("profile-editor");

    h.state().edit("shadow.depthBias", 0.0);
    h.state().edit("shadow.slopeScaledDepthBias", 0.0);
    h.state().edit("shadow.normalOffset", 0.0);
    h.frame(3);
    ASSERT_TRUE(p.profile && p.profile->ok);
    EXPECT_GT(p.profile->acne, 0) << "zero bias: the same line now shows acne";
}

}  // namespace shadowlab::editor::test
