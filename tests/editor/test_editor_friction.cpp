// Friction mended (issue 13): the view mode is not a preset change, camera drags start only on a press inside the
// view, Reset view returns to the preset's camera, Escape closes an open combo.
#include "editor_harness.h"
#include "frame/orbit_camera.h"

namespace shadowlab::editor::test {

namespace {

constexpr int kEscape = 256;  // GLFW_KEY_ESCAPE, ImGui's io.KeyMap[ImGuiKey_Escape] in the harness

class EditorFriction : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
        harness = std::make_unique<EditorHarness>(testOptions(folder));
        harness->settle();
    }
    glm::dvec3 eye() { return harness->editor().orbitCamera()->eye(); }
    std::filesystem::path folder;
    std::unique_ptr<EditorHarness> harness;
};

}  // namespace

TEST_F(EditorFriction, SwitchingTheViewModeDoesNotMarkThePresetChanged) {
    EditorHarness& h = *harness;
    h.click("view");
    h.click("view=shadow");
    EXPECT_EQ(h.state().settings.view, ViewMode::Shadow) << "the viewport shows the shadow factor";
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
    EXPECT_EQ(h.editor().windowTitle().find('*'), std::string::npos) << h.editor().windowTitle();
    // A real edit still marks it; Revert undoes the edit and leaves the view the user chose.
    h.click("shadow.resolution=1K");
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings));
    h.click("preset.revert");
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
    EXPECT_EQ(h.state().settings.lights[0].shadow.resolution, 2048);
    EXPECT_EQ(h.state().settings.view, ViewMode::Shadow);
}

TEST_F(EditorFriction, APressThatFirstMovesOntoTheToolbarDoesNotOrbit) {
    EditorHarness& h = *harness;
    const glm::dvec3 before = eye();
    const ControlRect view = h.rect("viewport.image");
    const ControlRect toolbar = h.rect("viewport.frustum");
    // The window system delivered the toolbar click before the cursor's move: ImGui sees a press on the view...
    h.moveMouse(view.centerX(), view.centerY());
    ImGui::GetIO().MouseDown[0] = true;
    h.frame();
    // ...then the cursor arrives on the toolbar, the whole distance in one move.
    h.moveMouse(toolbar.centerX(), toolbar.centerY());
    h.moveMouse(toolbar.centerX() + 5.0f, toolbar.centerY());
    ImGui::GetIO().MouseDown[0] = false;
    h.frame(2);
    EXPECT_LT(glm::length(eye() - before), 1e-9) << "the camera orbited on a click outside the view";

    // A press on the toolbar dragged into the view does not orbit either.
    h.drag("viewport.frustum", 0.0f, 200.0f);
    EXPECT_LT(glm::length(eye() - before), 1e-9);

    // A drag that starts in the view still orbits, and may leave the view while it goes on.
    h.drag("viewport.image", 40.0f, -(view.centerY() - toolbar.centerY()), 0, 8);
    EXPECT_GT(glm::length(eye() - before), 0.1);
}

TEST_F(EditorFriction, ResetViewReturnsToThePresetsCamera) {
    EditorHarness& h = *harness;
    const glm::dvec3 before = eye();
    h.drag("viewport.image", 120.0f, 30.0f);
    h.wheel("viewport.image", 3.0f);
    ASSERT_GT(glm::length(eye() - before), 0.1);
    h.click("viewport.resetView");
    EXPECT_LT(glm::length(eye() - before), 1e-6);
    h.saveWindow("reset-view");  // the toolbar with its Reset view button
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
}

TEST_F(EditorFriction, EscapeClosesAnOpenCombo) {
    EditorHarness& h = *harness;
    h.click("view");
    h.frame();
    ASSERT_TRUE(h.reveal("view=lit")) << "the view combo opened";
    h.pressKey(kEscape);
    h.frame();
    EXPECT_FALSE(h.hasControl("view=lit")) << "Escape left the combo open";
    EXPECT_EQ(h.state().settings.view, ViewMode::Lit);
    // The next click works normally (nothing swallowed by a stale popup).
    h.click("shadow.resolution=1K");
    EXPECT_EQ(h.state().settings.lights[0].shadow.resolution, 1024);
}

}  // namespace shadowlab::editor::test
