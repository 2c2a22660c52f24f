// Issue 19: "Don't save" before a scene switch declines the edits, but the switch can fail: the edits are kept until
// the new scene has loaded (they used to be reverted before the load started, so a failed load lost them).
#include "editor_harness.h"

namespace shadowlab::editor::test {

TEST(EditorDontSaveIssue19, AFailedSceneLoadKeepsTheDeclinedEditsAndASuccessfulOneDropsThem) {
    const std::filesystem::path folder = testFolder("dont-save-failed-load");
    EditorHarness h(testOptions(folder));
    h.settle();
    h.click("shadow.resolution=1K");
    ASSERT_EQ(h.state().settings.lights[0].shadow.resolution, 1024);
    ASSERT_TRUE(h.state().preset.dirty(h.state().settings));
    const Settings edited = h.state().settings;

    const std::string missing = (folder / "missing.glb").string();
    h.editor().requestScene(missing);
    h.frame(3);  // a modal is sized in its first frames: click it once it is placed
    ASSERT_TRUE(h.reveal("dialog.dontSave")) << "the unsaved-changes question was not asked";
    h.click("dialog.dontSave");
    h.settle();
    EXPECT_EQ(h.state().sceneSpec, "builtin:textbook") << "the failed load keeps the scene";
    EXPECT_TRUE(h.state().settings == edited) << "the failed load threw the edits away";
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings));
    const Message* said = h.state().lastMessage();
    ASSERT_NE(said, nullptr);
    EXPECT_TRUE(said->error);
    EXPECT_NE(said->text.find("missing.glb"), std::string::npos) << said->text;
    EXPECT_NE(said->text.find("unsaved edits are kept"), std::string::npos) << said->text;

    // A later load that succeeds without a question (the user saved nothing, said nothing): asked again, and
    // "Don't save" now drops the edits once the scene is there.
    h.editor().requestScene("builtin:roof");
    h.frame(3);  // a modal is sized in its first frames: click it once it is placed
    ASSERT_TRUE(h.reveal("dialog.dontSave")) << "the edits are still unsaved: asked again";
    h.click("dialog.dontSave");
    h.settle();
    EXPECT_EQ(h.state().sceneSpec, "builtin:roof");
    EXPECT_EQ(h.state().settings.lights[0].shadow.resolution, h.state().preset.baseline().lights[0].shadow.resolution);
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
}

}  // namespace shadowlab::editor::test
