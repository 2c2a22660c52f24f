// A preset saved from the editor records the scene and the camera it was tuned from: loading it brings that view
// back; on another scene the camera auto-frames and the status line says so.
#include "editor_harness.h"
#include "frame/orbit_camera.h"
#include "settings/preset_io.h"

namespace shadowlab::editor::test {

namespace {

class EditorPresetScene : public ::testing::Test {
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

bool said(const EditorState& state, const std::string& part) {
    for (const Message& m : state.messages)
        if (m.text.find(part) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_F(EditorPresetScene, SavingRecordsTheSceneAndTheCameraShownAndLoadingBringsTheViewBack) {
    EditorHarness& h = *harness;
    // Nothing moved yet: the saved camera is what auto-framing chose, and it stays auto-framed.
    h.click("shadow.resolution=1K");
    h.pressKey(keys::kS, /*ctrl=*/true);
    h.selectAllAndType("framed");
    PresetLoadResult framed = loadPresetFile((folder / "user-presets" / "framed.json").string());
    ASSERT_TRUE(framed.settings) << framed.errors.front();
    EXPECT_EQ(framed.scene, "builtin:textbook");
    EXPECT_TRUE(framed.settings->camera.autoFrame);
    EXPECT_LT(glm::length(framed.settings->camera.position - eye()), 1e-9) << "the position actually shown";

    // Orbit, then save: the camera is recorded as shown, no longer auto-framed.
    h.drag("viewport.image", 120.0f, 40.0f);
    const glm::dvec3 tunedEye = eye();
    const glm::dvec3 tunedTarget = h.editor().orbitCamera()->target();
    h.click("preset.saveAs");
    h.selectAllAndType("tuned-view");
    PresetLoadResult tuned = loadPresetFile((folder / "user-presets" / "tuned-view.json").string());
    ASSERT_TRUE(tuned.settings) << tuned.errors.front();
    EXPECT_EQ(tuned.scene, "builtin:textbook");
    EXPECT_FALSE(tuned.settings->camera.autoFrame);
    EXPECT_LT(glm::length(tuned.settings->camera.position - tunedEye), 1e-9);
    EXPECT_LT(glm::length(tuned.settings->camera.target - tunedTarget), 1e-9);
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings)) << "saving leaves nothing unsaved";

    // Frame the scene (the view changes), then load the tuned preset: its view comes back.
    h.click("viewport.frame");
    h.click("preset.shipped=acne");
    ASSERT_GT(glm::length(eye() - tunedEye), 0.1);
    h.editor().requestPreset((folder / "user-presets" / "tuned-view.json").string(), false);
    h.frame(2);
    ASSERT_EQ(h.state().preset.name(), "tuned-view") << (h.state().lastMessage() ? h.state().lastMessage()->text : "");
    EXPECT_LT(glm::length(eye() - tunedEye), 1e-6);
    EXPECT_FALSE(said(h.state(), "tuned on"));

    // On another scene: auto-framed there, and the status line names both scenes.
    h.editor().requestScene("builtin:grazing");
    h.settle();
    ASSERT_EQ(h.state().sceneSpec, "builtin:grazing");
    EXPECT_TRUE(said(h.state(), "tuned on builtin:textbook, shown here on builtin:grazing"));
    EXPECT_GT(glm::length(eye() - tunedEye), 1e-3) << "the textbook camera was kept on another scene";
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings)) << "the framing rule is no edit";
}

}  // namespace shadowlab::editor::test

namespace shadowlab::editor::test {

TEST_F(EditorPresetScene, AScreenshotCarriesThePresetAndTheSceneAndLoadsBackAsAPreset) {
    EditorHarness& h = *harness;
    h.click("shadow.resolution=1K");
    h.drag("viewport.image", 60.0f, 10.0f);
    h.click("viewport.screenshot");
    h.frame(2);
    const std::string shot = h.state().lastScreenshot;
    ASSERT_TRUE(std::filesystem::exists(shot)) << shot;
    PresetLoadResult loaded = loadPresetFile(shot);
    ASSERT_TRUE(loaded.settings) << loaded.errors.front();
    EXPECT_EQ(loaded.scene, "builtin:textbook");
    EXPECT_EQ(loaded.settings->lights[0].shadow.resolution, 1024);
    EXPECT_LT(glm::length(loaded.settings->camera.position - eye()), 1e-9) << "the camera of the picture";

    // Loading the picture as a preset brings its view back; it is never saved over (Save asks for a name).
    h.click("preset.revert");
    h.click("viewport.frame");
    h.editor().requestPreset(shot, false);
    h.frame(2);
    EXPECT_EQ(h.state().settings, *loaded.settings);
    EXPECT_LT(glm::length(eye() - loaded.settings->camera.position), 1e-6);
    EXPECT_FALSE(h.state().preset.canSaveInPlace());
}

}  // namespace shadowlab::editor::test
