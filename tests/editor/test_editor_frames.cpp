// Frames: idle frames run no pass, a camera move runs only the main pass, the camera controls, the viewer.
#include "editor_harness.h"
#include "frame/camera.h"
#include "frame/orbit_camera.h"

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
    h.frame(5);
    EXPECT_GE(h.state().renderedFrames, rendered + 4);
    EXPECT_TRUE(h.state().stats.shadowPass.ran);
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
}

}  // namespace shadowlab::editor::test
