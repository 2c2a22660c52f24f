// Screenshots and scenes: F12 writes the viewport, a failed write says why, a bad scene path or a dropped file that
// is not a scene leaves the editor running on its scene with a message; a real glTF loads without blocking.
#include "editor_harness.h"

#include "image/image_io.h"

#include <fstream>

namespace shadowlab::editor::test {

namespace {

class EditorFiles : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    std::filesystem::path folder;
};

std::vector<std::filesystem::path> filesIn(const std::filesystem::path& dir, const std::string& suffix) {
    std::vector<std::filesystem::path> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
        if (e.path().string().size() >= suffix.size() &&
            e.path().string().compare(e.path().string().size() - suffix.size(), suffix.size(), suffix) == 0)
            out.push_back(e.path());
    return out;
}

}  // namespace

TEST_F(EditorFiles, F12WritesTheViewportAsAPngAndSaysWhere) {
    EditorHarness h(testOptions(folder));
    h.settle();
    h.pressKey(keys::kF12);
    h.frame();
    const auto pngs = filesIn(folder / "screenshots", ".png");
    ASSERT_EQ(pngs.size(), 1u);
    std::string error;
    const auto image = readPng(pngs[0].string(), &error);
    ASSERT_TRUE(image) << error;
    EXPECT_EQ(image->width, h.editor().viewportTarget().width());
    EXPECT_EQ(image->height, h.editor().viewportTarget().height());
    long bright = 0, dark = 0;
    for (std::size_t i = 0; i < image->pixels.size(); i += std::size_t(image->channels)) {
        bright += image->pixels[i] > 150;
        dark += image->pixels[i] < 60;
    }
    EXPECT_GT(bright, 1000) << "lit floor";
    EXPECT_GT(dark, 100) << "shadows";
    EXPECT_EQ(h.state().lastScreenshot, pngs[0].string());

    // With the shadow map too, from the button.
    h.click("viewport.screenshotWithMap");
    h.click("viewport.screenshot");
    h.frame();
    EXPECT_EQ(filesIn(folder / "screenshots", ".exr").size(), 1u);
    EXPECT_EQ(filesIn(folder / "screenshots", ".png").size(), 3u);
}

TEST_F(EditorFiles, AScreenshotThatCannotBeWrittenSaysWhyAndTheEditorGoesOn) {
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "not-a-folder") << "x";
    EditorOptions options = testOptions(folder);
    options.screenshotDir = (folder / "not-a-folder" / "shots").string();
    EditorHarness h(options);
    h.settle();
    h.pressKey(keys::kF12);
    h.frame();
    ASSERT_NE(h.state().lastMessage(), nullptr);
    EXPECT_TRUE(h.state().lastMessage()->error);
    EXPECT_NE(h.state().lastScreenshot.find("failed"), std::string::npos) << h.state().lastScreenshot;
    h.pressKey(keys::kF12, /*ctrl=*/true);  // Ctrl+F12 asks the host for the whole window
    EXPECT_TRUE(h.editor().takeWindowScreenshotRequest().has_value());
}

TEST_F(EditorFiles, ABadScenePathLeavesTheSceneWithAMessage) {
    EditorHarness h(testOptions(folder));
    h.settle();
    const Scene* before = h.state().scene.get();
    h.click("scene.path");
    h.selectAllAndType((folder / "no-such-scene.gltf").string());
    h.settle();
    EXPECT_EQ(h.state().scene.get(), before);
    ASSERT_NE(h.state().lastMessage(), nullptr);
    EXPECT_TRUE(h.state().lastMessage()->error);
    EXPECT_NE(h.state().lastMessage()->text.find("no-such-scene.gltf"), std::string::npos);

    h.editor().dropFiles({(folder / "notes.txt").string()});
    h.frame();
    EXPECT_NE(h.state().lastMessage()->text.find("not a .gltf"), std::string::npos);
    EXPECT_EQ(h.state().scene.get(), before);
}

TEST_F(EditorFiles, ADroppedGltfLoadsWhileTheWindowKeepsDrawing) {
    const std::string box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";
    ASSERT_TRUE(std::filesystem::exists(box)) << box << ": assimp-testmodels (scripts/install-deps) is missing";
    EditorHarness h(testOptions(folder));
    h.settle();
    h.editor().dropFiles({box});
    h.frame();
    h.settle();
    EXPECT_EQ(h.state().sceneSpec, box);
    EXPECT_EQ(h.state().recentFiles.items().front(), box);
    EXPECT_TRUE(h.state().stats.ok);
}

TEST_F(EditorFiles, ABigSceneLoadsOnAThreadWhileFramesKeepComing) {
    const std::string helmet =
        std::string(SHADOWLAB_SOURCE_DIR) + "/../shared/scenes/FlightHelmet_geometry/FlightHelmet.gltf";
    if (!std::filesystem::exists(helmet)) GTEST_SKIP() << helmet << " (the shared scenes) is not here";
    EditorHarness h(testOptions(folder));
    h.settle();
    h.click("scene.path");
    h.pressKey('A', /*ctrl=*/true);
    h.typeText(helmet);
    // The frame that sees Enter asks for the load and returns without it: a load on the UI thread would have
    // switched the scene within that frame.
    h.setKey(EditorHarness::kEnterKey, true);
    h.frame();
    h.setKey(EditorHarness::kEnterKey, false);
    EXPECT_NE(h.state().sceneSpec, helmet) << "the load blocked the frame that asked for it";
    int framesBeforeAdopted = 0;
    // Until the load is adopted, however long a loaded machine takes (the ceiling reports it).
    ASSERT_TRUE(h.framesUntil(
        [&] {
            if (h.state().sceneSpec == helmet) return true;
            ++framesBeforeAdopted;
            if (h.state().loading) EXPECT_TRUE(h.reveal("scene.progress"));
            return false;
        },
        "the helmet's load to be adopted"));
    EXPECT_GT(framesBeforeAdopted, 0);
    h.settle();
    EXPECT_GT(h.state().stats.sceneTriangles, 90000u);
}

TEST_F(EditorFiles, PickingABuiltInSceneLoadsIt) {
    EditorHarness h(testOptions(folder));
    h.settle();
    h.click("scene.builtin");
    h.click("scene.builtin=fence");
    h.settle();
    EXPECT_EQ(h.state().sceneSpec, "builtin:fence");
    EXPECT_GT(h.state().stats.alphaTestedCasters, 0);
}

TEST(EditorStart, AStartSceneThatFailsToLoadFallsBackToTheDefaultWithAMessage) {
    const auto folder = testFolder("bad-start-scene");
    EditorOptions options = testOptions(folder);
    options.scene = (folder / "broken.glb").string();
    std::ofstream(folder / "broken.glb") << "not a glb";
    EditorHarness h(options);
    h.settle();
    ASSERT_TRUE(h.state().scene);
    EXPECT_EQ(h.state().sceneSpec, kDefaultSceneSpec);
    bool reported = false;
    for (const Message& m : h.state().messages) reported |= m.error && m.text.find("broken.glb") != std::string::npos;
    EXPECT_TRUE(reported);
}

}  // namespace shadowlab::editor::test
