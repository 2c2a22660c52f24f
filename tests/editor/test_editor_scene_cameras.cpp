// The file's cameras, fly mode, the picked pivot and the Outliner's "casts shadows" boxes, driven through ImGui input
// on tests/data/scenes/sky_box_city.gltf (a city inside a closed sky box, a street camera inside it).
#include "editor_harness.h"
#include "frame/orbit_camera.h"
#include "settings/preset_io.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace shadowlab::editor::test {

namespace {

const std::string kCity = std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/sky_box_city.gltf";

class EditorSceneCameras : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
        EditorOptions options = testOptions(folder);
        options.scene = kCity;
        harness = std::make_unique<EditorHarness>(options);
        harness->settle();
        ASSERT_TRUE(harness->state().scene);
        ASSERT_EQ(harness->state().scene->cameras.size(), 3u);
    }
    const OrbitCamera& orbit() { return *harness->editor().orbitCamera(); }
    // Chooses an entry of the Scene panel's camera combo as a user does: open it, click the entry.
    void chooseCamera(int index) {
        harness->click("scene.camera");
        harness->click("scene.camera=" + std::to_string(index));
    }
    // Holds the right button on the view (fly mode) for `frames` frames of `seconds` each with `key` down.
    void fly(int key, int frames, double seconds) {
        EditorHarness& h = *harness;
        const ControlRect view = h.rect("viewport.image");
        h.moveMouse(view.centerX(), view.centerY());
        ImGui::GetIO().MouseDown[1] = true;
        h.frame();
        h.setKey(key, true);
        for (int i = 0; i < frames; ++i) {
            h.advanceClock(seconds);
            h.frame();
        }
        h.setKey(key, false);
        ImGui::GetIO().MouseDown[1] = false;
        h.frame(2);
    }
    std::filesystem::path folder;
    std::unique_ptr<EditorHarness> harness;
};

}  // namespace

TEST_F(EditorSceneCameras, ChoosingAFileCameraMovesTheViewToItAndTheChoiceIsSaved) {
    EditorHarness& h = *harness;
    const SceneCamera& street = h.state().scene->cameras[0];
    ASSERT_GT(glm::length(orbit().eye() - street.position), 1.0) << "auto-framed from outside the box at first";
    chooseCamera(0);
    EXPECT_EQ(h.state().settings.camera.sceneCamera, 0);
    EXPECT_LT(glm::length(orbit().eye() - street.position), 1e-6);
    EXPECT_GT(glm::dot(glm::normalize(orbit().target() - orbit().eye()), street.forward), 1.0 - 1e-6);
    EXPECT_NEAR(orbit().toCamera().fovYDeg, glm::degrees(street.yfovRad), 1e-6);

    // The orthographic "Top" camera stays orthographic in the view.
    chooseCamera(1);
    EXPECT_EQ(h.state().settings.camera.sceneCamera, 1);
    EXPECT_NEAR(orbit().toCamera().orthoHalfHeight, 12.0, 1e-9);

    // Saved with the preset while the view is still the camera's.
    chooseCamera(0);
    h.click("preset.saveAs");
    h.selectAllAndType("street");
    const PresetLoadResult saved = loadPresetFile((folder / "user-presets" / "street.json").string());
    ASSERT_TRUE(saved.settings) << saved.errors.front();
    EXPECT_EQ(saved.settings->camera.sceneCamera, 0);

    // Free camera: the view stays where it is.
    const glm::dvec3 eye = orbit().eye();
    chooseCamera(-1);
    EXPECT_EQ(h.state().settings.camera.sceneCamera, -1);
    EXPECT_LT(glm::length(orbit().eye() - eye), 1e-9);
}

TEST_F(EditorSceneCameras, FlyModeTravelsPerSecondOfTheClockAndLooksAroundTheEye) {
    EditorHarness& h = *harness;
    chooseCamera(0);
    const glm::dvec3 start = orbit().eye();
    const glm::dvec3 forward = glm::normalize(orbit().target() - start);
    const double speed = orbit().flySpeed() * h.state().flySpeedFactor;

    // W for one second in ten frames: one second's travel along the view.
    fly(keys::kW, 10, 0.1);
    const glm::dvec3 moved = orbit().eye() - start;
    EXPECT_NEAR(glm::length(moved), speed * 1.0, 1e-6 * speed);
    EXPECT_GT(glm::dot(glm::normalize(moved), forward), 1.0 - 1e-9);

    // The same second in forty frames: the same distance again (frame-rate independent).
    const glm::dvec3 before = orbit().eye();
    fly(keys::kW, 40, 0.025);
    EXPECT_NEAR(glm::length(orbit().eye() - before), speed * 1.0, 1e-6 * speed);

    // E rises.
    const double height = orbit().eye().y;
    fly(keys::kE, 5, 0.1);
    // Along the view's up, which leans back as the view looks down: its height share is cos(pitch).
    EXPECT_NEAR(orbit().eye().y - height, speed * 0.5 * std::sqrt(1.0 - forward.y * forward.y), 1e-6 * speed);

    // Right drag without keys: mouse look; the eye stays.
    const glm::dvec3 eye = orbit().eye();
    const glm::dvec3 lookBefore = orbit().target() - eye;
    h.drag("viewport.image", 80.0f, 0.0f, /*button=*/1);
    EXPECT_LT(glm::length(orbit().eye() - eye), 1e-9);
    EXPECT_GT(glm::length(glm::normalize(orbit().target() - eye) - glm::normalize(lookBefore)), 0.1);

    // The wheel while flying sets the speed.
    const ControlRect view = h.rect("viewport.image");
    h.moveMouse(view.centerX(), view.centerY());
    ImGui::GetIO().MouseDown[1] = true;
    h.frame();
    ImGui::GetIO().MouseWheel = 2.0f;
    h.frame();
    ImGui::GetIO().MouseDown[1] = false;
    h.frame(2);
    EXPECT_NEAR(h.state().flySpeedFactor, 1.5625, 1e-9);
    ASSERT_TRUE(h.state().lastMessage());
    EXPECT_NE(h.state().lastMessage()->text.find("fly speed: "), std::string::npos) << h.state().lastMessage()->text;
}

TEST_F(EditorSceneCameras, AltClickSetsTheOrbitPivotOnTheSurfaceUnderTheCursor) {
    EditorHarness& h = *harness;
    chooseCamera(0);  // inside the box, looking at the ground past the tower
    const glm::dvec3 eye = orbit().eye();
    const ControlRect view = h.rect("viewport.image");
    // Low in the view: the ground in front of the camera.
    const float x = view.x + view.w * 0.5f, y = view.y + view.h * 0.9f;
    h.setKey(keys::kLeftAlt, true);
    h.clickAt(x, y);
    h.setKey(keys::kLeftAlt, false);
    h.frame();
    EXPECT_LT(glm::length(orbit().eye() - eye), 1e-6) << "the eye stays";
    EXPECT_NEAR(orbit().target().y, 0.0, 0.05) << "the pivot is on the ground (y = 0)";
    EXPECT_FALSE(h.state().probe.request) << "an Alt+click is no probe";
    // Orbiting now turns around that point.
    const glm::dvec3 pivot = orbit().target();
    h.drag("viewport.image", 60.0f, 0.0f);
    EXPECT_LT(glm::length(orbit().target() - pivot), 1e-9);
}

TEST_F(EditorSceneCameras, OutlinerBoxStopsANodeCastingInTheMapsAndThePreset) {
    EditorHarness& h = *harness;
    chooseCamera(0);
    h.frame(2);
    // The newest shadow pass's casters (drawn or outside the light's volume).
    const auto casters = [&] { return h.state().lastShadowPass.castersDrawn + h.state().lastShadowPass.castersSkipped; };
    ASSERT_EQ(casters(), 3) << "ground, tower and sky box cast";
    h.click("outliner.casts=Root/City/SkyBox");
    h.frame(2);
    EXPECT_EQ(h.state().settings.casters.excluded, std::vector<std::string>{"Root/City/SkyBox"});
    EXPECT_EQ(casters(), 2);
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings));

    // A subtree: unticking City takes the tower and the ground too: no caster is left, the map is only cleared.
    h.click("outliner.casts=Root/City");
    h.frame(2);
    ASSERT_FALSE(h.state().stats.views.empty());
    EXPECT_NE(h.state().stats.views.front().reason.find("no caster"), std::string::npos)
        << h.state().stats.views.front().reason;
    h.click("outliner.casts=Root/City");  // ticked again: only the sky box stays out
    h.frame(2);
    EXPECT_EQ(h.state().settings.casters.excluded, std::vector<std::string>{"Root/City/SkyBox"});
    EXPECT_EQ(casters(), 2);
    h.saveWindow("outliner-sky-box-excluded");
}

}  // namespace shadowlab::editor::test
