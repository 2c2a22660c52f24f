// Frames: idle frames run no pass, a camera move runs only the main pass, the camera controls, the viewer.
#include "editor_harness.h"
#include "frame/camera.h"
#include "frame/orbit_camera.h"

#include <chrono>
#include <cstdio>

namespace shadowlab::editor::test {

namespace {

class EditorFrames : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
        harness = std::make_unique<EditorHarness>(testOptions(folder));
        harness->settle();
    }
    std::filesystem::path folder;
    std::unique_ptr<EditorHarness> harness;
};

}  // namespace

TEST_F(EditorFrames, IdleFramesRunNoPassAndOrbitingRunsOnlyTheMainPass) {
    EditorHarness& h = *harness;
    const long rendered = h.state().renderedFrames;
    const long idle = h.state().idleFrames;
    h.frame(10);
    EXPECT_EQ(h.state().renderedFrames, rendered);
    EXPECT_EQ(h.state().idleFrames, idle + 10);
    EXPECT_FALSE(h.editor().busy());

    const glm::dvec3 eye = h.editor().orbitCamera()->eye();
    h.drag("viewport.image", 80.0f, 20.0f);
    EXPECT_GT(glm::length(h.editor().orbitCamera()->eye() - eye), 0.1);
    EXPECT_GT(h.state().renderedFrames, rendered);
    EXPECT_FALSE(h.state().stats.shadowPass.ran) << h.state().stats.shadowPass.reason;
    EXPECT_TRUE(h.state().stats.mainPass.ran);
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings)) << "the view camera is not a setting";
}

TEST_F(EditorFrames, WheelZoomsPanMovesTheTargetAndFFramesTheScene) {
    EditorHarness& h = *harness;
    const double distance = h.editor().orbitCamera()->distance();
    h.wheel("viewport.image", 2.0f);
    EXPECT_LT(h.editor().orbitCamera()->distance(), distance * 0.9);
    const glm::dvec3 target = h.editor().orbitCamera()->target();
    h.drag("viewport.image", 60.0f, 0.0f, /*button=*/2);
    EXPECT_GT(glm::length(h.editor().orbitCamera()->target() - target), 0.1);
    const glm::dvec3 panned = h.editor().orbitCamera()->target();
    h.drag("viewport.image", 0.0f, 40.0f, 0, 8, /*shift=*/true);
    EXPECT_GT(glm::length(h.editor().orbitCamera()->target() - panned), 0.1);
    h.moveMouse(h.rect("viewport.image").centerX(), h.rect("viewport.image").centerY());
    h.pressKey(keys::kF);
    // F fills the view with the scene from the current direction (auto-framing's fit): the pan is undone, the target
    // is back inside the scene, and framing the result again moves nothing.
    const OrbitCamera& orbit = *h.editor().orbitCamera();
    EXPECT_GT(glm::length(orbit.target() - panned), 0.1);
    const glm::dvec3 center(h.state().scene->bounds.center());
    EXPECT_LT(glm::length(orbit.target() - center), double(h.state().scene->bounds.radius()));
    Camera again = orbit.toCamera();
    const ImVec4 view = h.editor().viewportRect();
    frameScene(again, *h.state().scene, double(view.z) / double(view.w));
    EXPECT_LT(glm::length(again.target - orbit.target()), 1e-6);
    EXPECT_LT(glm::length(again.position - orbit.eye()), 1e-6);
}

TEST_F(EditorFrames, ShadowMapViewerZoomsAndShowsTheDepthUnderTheCursor) {
    EditorHarness& h = *harness;
    const ControlRect map = h.rect("viewer.image");
    h.wheel("viewer.image", 3.0f);
    EXPECT_GT(h.state().viewer.zoomPan.zoom(), 1.5);
    h.moveMouse(map.centerX(), map.centerY());
    h.frame(2);
    ASSERT_TRUE(h.state().viewer.hoverTexel.has_value());
    ASSERT_TRUE(h.state().viewer.hoverDepth.has_value());
    EXPECT_GE(*h.state().viewer.hoverDepth, 0.0f);
    EXPECT_LE(*h.state().viewer.hoverDepth, 1.0f);
    const long rendered = h.state().renderedFrames;
    h.click("viewer.fit");
    EXPECT_DOUBLE_EQ(h.state().viewer.zoomPan.zoom(), 1.0);
    EXPECT_EQ(h.state().renderedFrames, rendered) << "the viewer re-draws its picture, not the scene";
}

TEST_F(EditorFrames, LightAnimationPreviewsWithoutChangingThePreset) {
    EditorHarness& h = *harness;
    h.click("light.animate");
    EXPECT_TRUE(h.state().animateLight);
    const long rendered = h.state().renderedFrames;
    // The light turns with the editor's clock: a frame on a clock that stood still shows the same picture.
    h.frame();
    const long still = h.state().renderedFrames;
    h.frame(3);
    EXPECT_EQ(h.state().renderedFrames, still) << "the animation moved while the clock stood still";
    for (int i = 0; i < 5; ++i) {
        h.advanceClock(1.0 / 60.0);
        h.frame();
    }
    EXPECT_GE(h.state().renderedFrames, rendered + 5);
    EXPECT_TRUE(h.state().stats.shadowPass.ran);
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
}

}  // namespace shadowlab::editor::test

namespace shadowlab::editor::test {

// Typing a path, hovering and opening a combo change only the UI: the viewport keeps its last picture and the
// renderer runs no pass (on llvmpipe a pass per key made typing lag by a frame per key). The per-frame time of such
// frames is printed (the README quotes it).
TEST_F(EditorFrames, UiOnlyFramesRunNoPass) {
    EditorHarness& h = *harness;
    h.click("scene.path");
    h.pressKey('A', /*ctrl=*/true);
    h.pressKey(259);  // GLFW_KEY_BACKSPACE: the field is empty
    h.frame(2);
    ASSERT_EQ(h.state().scenePathInput, "");
    const long rendered = h.state().renderedFrames;
    const long idle = h.state().idleFrames;
    const std::string typed = "/tmp/some/scene/file-name.gltf";
    const auto start = std::chrono::steady_clock::now();
    for (char c : typed) h.typeText(std::string(1, c));  // one frame per key, as a typist's events arrive
    const double perKeyMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / double(typed.size());
    EXPECT_EQ(h.state().scenePathInput, typed);
    EXPECT_EQ(h.state().renderedFrames, rendered) << "a key typed into a text field rendered the scene";
    EXPECT_EQ(h.state().idleFrames, idle + long(typed.size()));
    // Hover the toolbar, open the view combo and close it with Escape: still no pass.
    h.moveMouse(h.rect("viewport.frame").centerX(), h.rect("viewport.frame").centerY());
    h.click("view");
    ASSERT_TRUE(h.hasControl("view=lit"));
    h.pressKey(256);  // GLFW_KEY_ESCAPE
    EXPECT_EQ(h.state().renderedFrames, rendered);
    // For scale: a frame that does render (the camera moved).
    const auto moved = std::chrono::steady_clock::now();
    h.drag("viewport.image", 40.0f, 0.0f, 0, 4);
    const long passes = h.state().renderedFrames - rendered;
    const double frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - moved).count() / 8.0;  // drag: 8 frames
    EXPECT_GT(passes, 0);
    std::printf("per key: %.1f ms (no pass); a frame while orbiting: %.1f ms (%ld passes) at %dx%d\n", perKeyMs,
                frameMs, passes, h.width(), h.height());
}

}  // namespace shadowlab::editor::test
