// The presets workflow: shipped presets are read-only (Ctrl+S asks for a name in the user folder), the unsaved
// marker, revert, and switching with unsaved changes asks first.
#include "editor_harness.h"
#include "settings/preset_io.h"

#include <fstream>
#include <iterator>

namespace shadowlab::editor::test {

namespace {

class EditorPresets : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
        harness = std::make_unique<EditorHarness>(testOptions(folder));
        harness->settle();
    }
    Settings shipped(const std::string& name) const {
        PresetLoadResult loaded = loadPresetFile(std::string(SHADOWLAB_SOURCE_DIR) + "/presets/" + name + ".json");
        EXPECT_TRUE(loaded.settings.has_value());
        return loaded.settings.value_or(Settings{});
    }
    std::filesystem::path folder;
    std::unique_ptr<EditorHarness> harness;
};

}  // namespace

TEST_F(EditorPresets, ClickingAShippedPresetLoadsIt) {
    EditorHarness& h = *harness;
    h.click("preset.shipped=acne");
    EXPECT_EQ(h.state().settings, shipped("acne"));
    EXPECT_EQ(h.state().preset.name(), "acne");
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
}

TEST_F(EditorPresets, AnEditMarksThePresetUnsavedAndRevertUndoesIt) {
    EditorHarness& h = *harness;
    EXPECT_EQ(h.editor().windowTitle().find('*'), std::string::npos);
    const float cleanTab = h.rect("tab:Scene").w;
    h.click("shadow.resolution=1K");
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings));
    EXPECT_NE(h.editor().windowTitle().find('*'), std::string::npos);
    h.frame();
    EXPECT_GT(h.rect("tab:Scene").w, cleanTab) << "the Presets panel's tab shows the unsaved marker";
    EXPECT_TRUE(h.reveal("preset.current"));
    h.click("preset.revert");
    EXPECT_EQ(h.state().settings, shipped("default"));
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
}

TEST_F(EditorPresets, CtrlSOnAShippedPresetSavesACopyInTheUserFolderThatLoadsBackEqual) {
    EditorHarness& h = *harness;
    h.click("shadow.resolution=1K");
    h.pressKey(keys::kS, /*ctrl=*/true);
    ASSERT_TRUE(h.reveal("saveAs.name")) << "Ctrl+S on a shipped preset opens Save As";
    h.selectAllAndType("my-tuned");
    const std::filesystem::path saved = folder / "user-presets" / "my-tuned.json";
    ASSERT_TRUE(std::filesystem::exists(saved));
    PresetLoadResult loaded = loadPresetFile(saved.string());
    ASSERT_TRUE(loaded.settings.has_value());
    EXPECT_EQ(*loaded.settings, h.state().settings);
    EXPECT_EQ(loaded.settings->lights[0].shadow.resolution, 1024);
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
    EXPECT_FALSE(h.state().preset.shipped());
    // The shipped file is untouched, and the user's copy is listed.
    EXPECT_EQ(shipped("default").lights[0].shadow.resolution, 2048);
    h.frame();
    EXPECT_TRUE(h.reveal("preset.user=my-tuned"));

    // Now a user preset: Ctrl+S saves in place, without asking.
    h.click("shadow.resolution=512");
    h.pressKey(keys::kS, /*ctrl=*/true);
    EXPECT_FALSE(h.hasControl("saveAs.name"));
    EXPECT_EQ(loadPresetFile(saved.string()).settings->lights[0].shadow.resolution, 512);
}

TEST_F(EditorPresets, YourOwnPresetsCanBeRenamedAndDeletedShippedOnesCannot) {
    EditorHarness& h = *harness;
    // A shipped preset: both buttons are drawn but do nothing (disabled).
    h.click("preset.rename");
    EXPECT_FALSE(h.hasControl("rename.name"));
    h.click("shadow.resolution=1K");
    h.pressKey(keys::kS, /*ctrl=*/true);
    h.selectAllAndType("first-name");
    const std::filesystem::path users = folder / "user-presets";
    ASSERT_TRUE(std::filesystem::exists(users / "first-name.json"));
    const std::string text = [&] {
        std::ifstream in(users / "first-name.json");
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();

    h.click("preset.rename");
    ASSERT_TRUE(h.reveal("rename.name"));
    h.selectAllAndType("second-name");
    EXPECT_FALSE(std::filesystem::exists(users / "first-name.json"));
    ASSERT_TRUE(std::filesystem::exists(users / "second-name.json"));
    EXPECT_EQ(h.state().preset.name(), "second-name");
    std::ifstream renamed(users / "second-name.json");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(renamed), {}), text) << "a rename rewrites nothing";
    h.frame();
    EXPECT_TRUE(h.reveal("preset.user=second-name"));

    // Delete moves the file into deleted/ (nothing the user saved is lost); the settings stay.
    const Settings before = h.state().settings;
    h.click("preset.delete");
    h.click("delete.ok");
    EXPECT_FALSE(std::filesystem::exists(users / "second-name.json"));
    EXPECT_TRUE(std::filesystem::exists(users / "deleted" / "second-name.json"));
    EXPECT_EQ(h.state().settings, before);
    EXPECT_FALSE(h.state().preset.canSaveInPlace());
    h.frame();
    ASSERT_TRUE(h.reveal("preset.save"));
    EXPECT_FALSE(h.hasControl("preset.user=second-name"));
}

TEST_F(EditorPresets, SwitchingPresetWithUnsavedChangesAsksFirst) {
    EditorHarness& h = *harness;
    h.click("shadow.resolution=1K");
    h.wheel("preset.shipped=default", -5.0f);  // "soft" sorts last: scroll the list down to it, as a user would
    h.click("preset.shipped=soft");
    ASSERT_TRUE(h.reveal("dialog.cancel")) << "the unsaved-changes question was not asked";
    h.click("dialog.cancel");
    EXPECT_EQ(h.state().settings.lights[0].shadow.resolution, 1024) << "Cancel keeps the edits";
    EXPECT_EQ(h.state().preset.name(), "default");

    h.click("preset.shipped=soft");
    h.click("dialog.dontSave");
    EXPECT_EQ(h.state().preset.name(), "soft");
    EXPECT_EQ(h.state().settings, shipped("soft"));

    // "Save" on a shipped preset goes through Save As, then switches.
    h.click("shadow.resolution=1K");
    h.wheel("preset.shipped=soft", 5.0f);  // back up to "acne", the first
    h.click("preset.shipped=acne");
    h.click("dialog.save");
    ASSERT_TRUE(h.reveal("saveAs.name"));
    h.selectAllAndType("soft-1k");
    EXPECT_TRUE(std::filesystem::exists(folder / "user-presets" / "soft-1k.json"));
    EXPECT_EQ(h.state().preset.name(), "acne");
}

TEST_F(EditorPresets, QuittingWithNothingUnsavedDoesNotAsk) {
    EditorHarness& h = *harness;
    h.pressKey(keys::kQ, /*ctrl=*/true);
    EXPECT_TRUE(h.editor().quitConfirmed()) << "nothing unsaved: Ctrl+Q quits at once";
}

TEST_F(EditorPresets, QuittingWithUnsavedChangesAsksAndCancelKeepsTheEditorOpen) {
    EditorHarness& h = *harness;
    h.click("shadow.resolution=4K");
    h.editor().requestQuit();  // what the window's close button does
    h.frame();
    ASSERT_TRUE(h.reveal("dialog.cancel"));
    h.click("dialog.cancel");
    EXPECT_FALSE(h.editor().quitConfirmed());
    h.pressKey(keys::kQ, /*ctrl=*/true);
    h.click("dialog.dontSave");
    EXPECT_TRUE(h.editor().quitConfirmed());
}

TEST_F(EditorPresets, SaveAsRefusesToReplaceAnExistingFileUnlessAsked) {
    EditorHarness& h = *harness;
    h.click("preset.saveAs");
    h.selectAllAndType("mine");
    ASSERT_TRUE(std::filesystem::exists(folder / "user-presets" / "mine.json"));
    h.click("shadow.resolution=4K");
    h.click("preset.saveAs");
    h.selectAllAndType("mine");
    ASSERT_TRUE(h.reveal("saveAs.replace")) << "an existing name must be confirmed";
    EXPECT_EQ(loadPresetFile((folder / "user-presets" / "mine.json").string()).settings->lights[0].shadow.resolution, 2048);
    h.click("saveAs.replace");
    EXPECT_EQ(loadPresetFile((folder / "user-presets" / "mine.json").string()).settings->lights[0].shadow.resolution, 4096);
}

TEST(EditorStart, ABadStartPresetIsReportedAndDefaultsAreUsed) {
    const auto folder = testFolder("bad-start-preset");
    EditorOptions options = testOptions(folder);
    options.preset = (folder / "missing.json").string();
    EditorHarness h(options);
    h.settle();
    EXPECT_EQ(h.state().settings, Settings{});
    ASSERT_FALSE(h.state().messages.empty());
    EXPECT_NE(h.state().messages.front().text.find("missing.json"), std::string::npos);
}

}  // namespace shadowlab::editor::test
