// Issue 19 §3: before an action whose crash would lose work the editor keeps the unsaved settings in an autosave
// file; a start that finds one (the last exit was not clean) offers to restore it; a save or a clean exit removes it.
#include "editor_harness.h"

#include "editor/autosave.h"
#include "settings/preset_io.h"

namespace shadowlab::editor::test {

namespace {

Settings shippedDefault() {
    const PresetLoadResult base = loadPresetFile(std::string(SHADOWLAB_SOURCE_DIR) + "/presets/default.json");
    EXPECT_TRUE(base.settings.has_value());
    return base.settings.value_or(Settings{});
}

// The shadow views of light 0 the newest frame drew, at this resolution.
int drawnResolution(EditorHarness& h) {
    for (const ShadowViewStats& v : h.state().stats.views)
        if (v.hasView && v.light == 0) return v.space.resolution;
    return 0;
}

}  // namespace

TEST(EditorAutosaveIssue19, AStartThatFindsAnAutosaveOffersItAndRestoreBringsTheSettingsBack) {
    const std::filesystem::path folder = testFolder("autosave-restore");
    const EditorOptions options = testOptions(folder);
    Autosave kept;
    kept.settings = shippedDefault();
    kept.settings.lights[0].shadow.resolution = 1024;
    kept.settings.lights[0].shadow.depthBias = 7.5f;
    kept.settings.filter.kernel = 5;
    kept.scene = "builtin:roof";
    kept.presetPath = std::string(SHADOWLAB_SOURCE_DIR) + "/presets/default.json";
    kept.presetShipped = true;
    ASSERT_EQ(writeAutosave(options.autosavePath, kept), "");

    EditorHarness h(options);
    h.settle();
    ASSERT_TRUE(h.reveal("restore.restore")) << "the autosave was not offered";
    EXPECT_TRUE(h.reveal("restore.discard"));
    EXPECT_FALSE(h.state().settings == kept.settings) << "restored before the user chose";
    h.click("restore.restore");
    h.settle();
    EXPECT_FALSE(h.hasControl("restore.restore"));
    EXPECT_TRUE(h.state().settings == kept.settings) << "the restored settings differ from the autosaved ones";
    EXPECT_EQ(h.state().sceneSpec, "builtin:roof");
    EXPECT_EQ(h.state().preset.name(), "default");
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings)) << "restored work is unsaved";
    EXPECT_TRUE(std::filesystem::exists(options.autosavePath)) << "kept until saved or a clean exit";

    // A save removes it (Save As: the shipped preset is read-only).
    h.click("preset.saveAs");
    h.frame();
    h.click("saveAs.name");
    h.selectAllAndType("restored");
    h.frame(2);
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
    EXPECT_FALSE(std::filesystem::exists(options.autosavePath)) << "a save leaves the autosave behind";
}

TEST(EditorAutosaveIssue19, DiscardRemovesItAndACleanExitLeavesNone) {
    const std::filesystem::path folder = testFolder("autosave-discard");
    const EditorOptions options = testOptions(folder);
    Autosave kept;
    kept.settings = shippedDefault();
    kept.settings.lights[0].shadow.resolution = 512;
    kept.scene = "builtin:textbook";
    ASSERT_EQ(writeAutosave(options.autosavePath, kept), "");
    EditorHarness h(options);
    h.settle();
    h.click("restore.discard");
    h.frame();
    EXPECT_FALSE(std::filesystem::exists(options.autosavePath));
    EXPECT_EQ(h.state().settings.lights[0].shadow.resolution, shippedDefault().lights[0].shadow.resolution);

    // Unsaved work, kept before a new map; then quitting with "Don't save" is a clean exit: nothing to offer.
    h.click("shadow.resolution=1K");
    EXPECT_TRUE(std::filesystem::exists(options.autosavePath));
    h.editor().requestQuit();
    h.frame(3);  // a modal is sized in its first frames: click it once it is placed
    h.click("dialog.dontSave");
    EXPECT_TRUE(h.editor().quitConfirmed());
    EXPECT_FALSE(std::filesystem::exists(options.autosavePath));
}

TEST(EditorAutosaveIssue19, ANewShadowMapKeepsTheUnsavedSettingsBeforeTheRendererMakesIt) {
    const std::filesystem::path folder = testFolder("autosave-before");
    const EditorOptions options = testOptions(folder);
    EditorHarness h(options);
    h.settle();
    h.drag("shadow.depthBias", 40.0f, 0.0f);  // unsaved, but nothing crash-prone: no autosave yet
    h.frame(2);
    ASSERT_TRUE(h.state().preset.dirty(h.state().settings));
    EXPECT_FALSE(std::filesystem::exists(options.autosavePath)) << "a bias drag compiles nothing";
    ASSERT_EQ(drawnResolution(h), 2048);

    // The click on "1K", frame by frame: the frame that sees the release applies the edit in its UI; the next
    // frame's renderer makes the new map. The autosave must exist in between.
    const ControlRect r = h.rect("shadow.resolution=1K");
    h.moveMouse(r.centerX(), r.centerY());
    ImGui::GetIO().MouseDown[0] = true;
    h.frame();
    ImGui::GetIO().MouseDown[0] = false;
    h.frame();
    ASSERT_EQ(h.state().settings.lights[0].shadow.resolution, 1024) << "the click did not apply";
    EXPECT_EQ(drawnResolution(h), 2048) << "the renderer already acted";
    const AutosaveRead kept = readAutosave(options.autosavePath);
    ASSERT_TRUE(kept.autosave.has_value()) << "no autosave before the new map: " << kept.error;
    EXPECT_TRUE(kept.autosave->settings == h.state().settings);
    EXPECT_EQ(kept.autosave->scene, "builtin:textbook");
    EXPECT_TRUE(kept.autosave->presetShipped);
    h.frame();
    EXPECT_EQ(drawnResolution(h), 1024);

    // A scene load keeps the newest unsaved settings before it starts (this one fails: the edits stay unsaved).
    h.drag("shadow.depthBias", 40.0f, 0.0f);
    h.frame(2);
    h.editor().requestScene((folder / "missing.glb").string());
    h.frame(3);  // a modal is sized in its first frames: click it once it is placed
    h.click("dialog.dontSave");
    const AutosaveRead beforeLoad = readAutosave(options.autosavePath);
    ASSERT_TRUE(beforeLoad.autosave.has_value()) << beforeLoad.error;
    EXPECT_EQ(beforeLoad.autosave->settings.lights[0].shadow.depthBias, h.state().settings.lights[0].shadow.depthBias);
    EXPECT_EQ(beforeLoad.autosave->scene, "builtin:textbook");
}

}  // namespace shadowlab::editor::test
