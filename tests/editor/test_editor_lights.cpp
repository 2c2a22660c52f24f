// Many lights in the editor, driven through ImGui's IO: the Lights panel adds, selects and removes lights; the
// Shadow map panel then edits only the selected light, and only that light's view re-renders; the viewer shows the
// view picked from the frame's views; Stats lists them.
#include "editor_harness.h"

#include <algorithm>

namespace shadowlab::editor::test {

namespace {

const ShadowViewStats* viewOf(const FrameStats& stats, std::size_t light) {
    auto it = std::find_if(stats.views.begin(), stats.views.end(),
                           [&](const ShadowViewStats& v) { return v.light == light && v.hasView; });
    return it == stats.views.end() ? nullptr : &*it;
}

class EditorLights : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
        harness = std::make_unique<EditorHarness>(testOptions(folder));
        harness->settle();
    }
    // Adds a second (directional) light from the Lights panel and lets both views render.
    void addSecondLight() {
        EditorHarness& h = *harness;
        ASSERT_EQ(h.state().settings.lights.size(), 1u);
        h.click("lights.add.directional");
        h.frame(2);
    }
    std::filesystem::path folder;
    std::unique_ptr<EditorHarness> harness;
};

}  // namespace

TEST_F(EditorLights, AddingALightAppendsItSelectsItAndTheFrameListsItsView) {
    EditorHarness& h = *harness;
    addSecondLight();
    ASSERT_EQ(h.state().settings.lights.size(), 2u);
    EXPECT_EQ(h.state().settings.lights[1].type, LightType::Directional);
    EXPECT_EQ(h.state().selectedLight, 1u) << "the new light is the one edited next";
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings)) << "adding a light is an unsaved change";
    ASSERT_TRUE(h.state().stats.ok) << h.state().stats.error;
    EXPECT_EQ(h.state().stats.lightCount, 2u);
    ASSERT_NE(viewOf(h.state().stats, 1), nullptr) << "the frame has no shadow view of the new light";
    EXPECT_NE(h.editor().renderer().viewMap(1, -1), nullptr);
    // Stats shows the table of views, and the panels editing the selected light name it.
    EXPECT_TRUE(h.reveal("stats.views"));
    EXPECT_TRUE(h.reveal("lights.select.1"));
}

TEST_F(EditorLights, DraggingTheSelectedLightsBiasChangesOnlyThatLightAndRerendersOnlyItsView) {
    EditorHarness& h = *harness;
    addSecondLight();
    h.click("lights.select.0");
    EXPECT_EQ(h.state().selectedLight, 0u);
    h.click("lights.select.1");
    ASSERT_EQ(h.state().selectedLight, 1u);
    const LightSettings light0 = h.state().settings.lights[0];
    const float bias1 = h.state().settings.lights[1].shadow.depthBias;
    h.drag("shadow.depthBias", 60.0f, 0.0f);
    h.frame();
    EXPECT_NE(h.state().settings.lights[1].shadow.depthBias, bias1) << "the drag did not reach light 1";
    EXPECT_EQ(h.state().settings.lights[0], light0) << "light 0 changed while light 1 was selected";

    const FrameStats& stats = h.state().stats;  // the newest frame that rendered: the drag's last step
    ASSERT_TRUE(stats.ok) << stats.error;
    const ShadowViewStats* view0 = viewOf(stats, 0);
    const ShadowViewStats* view1 = viewOf(stats, 1);
    ASSERT_NE(view0, nullptr);
    ASSERT_NE(view1, nullptr);
    EXPECT_TRUE(view1->ran) << view1->reason;
    EXPECT_FALSE(view0->ran) << "light 0's view re-rendered: " << view0->reason;
}

TEST_F(EditorLights, TheViewerShowsTheViewPickedFromTheFramesViews) {
    EditorHarness& h = *harness;
    addSecondLight();
    h.click("shadow.resolution=512");  // light 1 (selected): a map unlike light 0's 2048
    ASSERT_EQ(h.state().settings.lights[1].shadow.resolution, 512);
    EXPECT_EQ(h.state().settings.lights[0].shadow.resolution, 2048);
    h.frame(2);
    h.click("viewer.view");
    h.click("viewer.view=light 0");
    h.frame(2);
    ASSERT_NE(h.state().shownView(), nullptr);
    EXPECT_EQ(h.state().shownView()->light, 0u);
    EXPECT_EQ(h.state().shownView()->resolution, 2048);
    const std::vector<std::uint8_t> light0 = h.editor().mapViewPixels();

    h.click("viewer.view");
    h.click("viewer.view=light 1");
    h.frame(2);
    ASSERT_NE(h.state().shownView(), nullptr);
    EXPECT_EQ(h.state().shownView()->light, 1u);
    EXPECT_EQ(h.state().shownView()->resolution, 512);
    EXPECT_TRUE(h.state().viewer.error.empty()) << h.state().viewer.error;
    EXPECT_NE(h.editor().mapViewPixels(), light0) << "the viewer still shows light 0's map";
    h.saveWindow("viewer-light1");
}

TEST_F(EditorLights, RemovingLightsKeepsTheOthersAndZeroLightsRenderAmbientOnly) {
    EditorHarness& h = *harness;
    addSecondLight();
    h.click("shadow.resolution=512");  // marks light 1
    h.click("lights.select.0");
    h.click("lights.remove");
    ASSERT_EQ(h.state().settings.lights.size(), 1u);
    EXPECT_EQ(h.state().settings.lights[0].shadow.resolution, 512) << "the wrong light was removed";
    EXPECT_EQ(h.state().selectedLight, 0u);
    h.frame(2);
    ASSERT_TRUE(h.state().stats.ok) << h.state().stats.error;
    EXPECT_EQ(h.state().stats.lightCount, 1u);
    EXPECT_EQ(viewOf(h.state().stats, 1), nullptr);

    h.click("lights.remove");
    EXPECT_TRUE(h.state().settings.lights.empty());
    h.frame(2);
    EXPECT_TRUE(h.state().stats.ok) << h.state().stats.error;
    EXPECT_EQ(h.state().stats.lightCount, 0u);
    ASSERT_TRUE(h.reveal("panel:Shadow map"));
    EXPECT_FALSE(h.hasControl("shadow.depthBias")) << "a bias control with no light to edit";
    h.click("lights.add.point");
    ASSERT_EQ(h.state().settings.lights.size(), 1u);
    EXPECT_EQ(h.state().settings.lights[0].type, LightType::Point);
}

TEST_F(EditorLights, APointLightsCubeFacesArePickedOneByOneInTheViewer) {
    EditorHarness& h = *harness;
    h.click("lights.add.point");
    ASSERT_EQ(h.state().settings.lights.size(), 2u);
    h.frame(2);
    ASSERT_TRUE(h.state().stats.ok) << h.state().stats.error;
    int faces = 0;
    for (const ShadowViewStats& v : h.state().stats.views) faces += v.light == 1 && v.face >= 0 ? 1 : 0;
    EXPECT_EQ(faces, 6) << "a point light has six cube-face views";
    // -Y looks down at the textbook's floor from above: it holds the casters.
    const ShadowViewStats* down = nullptr;
    for (const ShadowViewStats& v : h.state().stats.views)
        if (v.light == 1 && v.face == 3) down = &v;
    ASSERT_NE(down, nullptr);
    ASSERT_TRUE(down->hasView);
    h.click("viewer.view");
    h.click("viewer.view=" + down->name);
    h.frame(2);
    ASSERT_NE(h.state().shownView(), nullptr);
    EXPECT_EQ(h.state().shownView()->light, 1u);
    EXPECT_EQ(h.state().shownView()->face, 3);
    EXPECT_TRUE(h.state().shownView()->space.perspective);
    EXPECT_TRUE(h.state().viewer.error.empty()) << h.state().viewer.error;
    h.saveWindow("viewer-point-face");

    // The viewport's volume is the selected light's: selecting light 0 redraws it as light 0's box.
    ASSERT_TRUE(h.state().showLightFrustum);
    const std::vector<std::uint8_t> pointVolume = h.editor().viewportTarget().readColor();
    h.click("lights.select.0");
    h.frame(2);
    EXPECT_NE(h.editor().viewportTarget().readColor(), pointVolume) << "the overlay still shows light 1's volume";
}

}  // namespace shadowlab::editor::test
