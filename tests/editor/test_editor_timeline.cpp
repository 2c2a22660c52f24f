// The Timeline panel on tests/data/scenes/animated_boxes.gltf, driven through ImGui input: choosing an animation,
// play, pause, loop, speed and scrubbing move animation.time, the shown scene follows it, and a saved preset records
// the time and the animation.
#include "editor_harness.h"
#include "editor/view_rows.h"
#include "settings/preset_io.h"

#include <glm/geometric.hpp>

namespace shadowlab::editor::test {

namespace {

const std::string kBoxes = std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/animated_boxes.gltf";

class EditorTimeline : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
        EditorOptions options = testOptions(folder);
        options.scene = kBoxes;
        harness = std::make_unique<EditorHarness>(options);
        harness->settle();
        ASSERT_TRUE(harness->state().scene);
        ASSERT_EQ(harness->state().scene->animations.size(), 3u);
    }
    // Where the shown scene puts node "Mover" (its instance's origin).
    glm::dvec3 mover() {
        const Scene& scene = *harness->state().scene;
        for (const Instance& i : scene.instances)
            if (i.node >= 0 && scene.nodes[std::size_t(i.node)].name == "Mover") return glm::dvec3(i.transform[3]);
        ADD_FAILURE() << "no Mover";
        return {};
    }
    double time() { return double(harness->state().settings.animation.time); }
    // `seconds` of the clock in frames a quarter second apart (the editor caps a frame's step at 0.25 s).
    void play(double seconds) {
        for (double t = 0.0; t < seconds - 1e-9; t += 0.25) {
            harness->advanceClock(0.25);
            harness->frame();
        }
    }
    std::filesystem::path folder;
    std::unique_ptr<EditorHarness> harness;
};

}  // namespace

TEST_F(EditorTimeline, PlayPauseLoopSpeedAndScrubMoveTheTimeAndTheScene) {
    EditorHarness& h = *harness;
    // At first every animation plays, posed at 0 s: Move's first key puts the mover at (-4, 1, 0).
    EXPECT_LT(glm::length(mover() - glm::dvec3(-4, 1, 0)), 1e-5);

    h.click("animation.play");
    h.click("animation.play=Move");
    EXPECT_EQ(h.state().settings.animation.play, "Move");

    h.click("timeline.play");
    EXPECT_TRUE(h.state().timeline.playing);
    play(0.5);
    h.frame();
    EXPECT_NEAR(time(), 0.5, 1e-5);
    EXPECT_LT(glm::length(mover() - glm::dvec3(0, 1, 0)), 1e-4) << "halfway between Move's first keys";

    h.click("timeline.play");  // pause
    EXPECT_FALSE(h.state().timeline.playing);
    play(1.0);
    EXPECT_NEAR(time(), 0.5, 1e-5) << "paused: the time holds";

    // Looping over Move's 0..2 s: 0.5 + 1.75 = 2.25 wraps to 0.25.
    h.click("timeline.play");
    play(1.75);
    EXPECT_NEAR(time(), 0.25, 1e-4);
    EXPECT_TRUE(h.state().timeline.playing);

    // Without loop it stops at the end.
    h.click("timeline.loop");
    EXPECT_FALSE(h.state().timeline.loop);
    play(2.0);
    EXPECT_NEAR(time(), 2.0, 1e-5);
    EXPECT_FALSE(h.state().timeline.playing);
    h.frame();
    EXPECT_LT(glm::length(mover() - glm::dvec3(4, 1, 4)), 1e-4) << "Move's last key";

    // Speed 2 (typed into the slider): a quarter second of the clock is half a second of animation.
    h.ctrlClick("timeline.speed");
    h.selectAllAndType("2");
    EXPECT_NEAR(h.state().timeline.speed, 2.0f, 1e-6);
    h.click("timeline.play");  // from the start again: it had run to the end
    EXPECT_NEAR(time(), 0.0, 1e-5);
    play(0.25);
    EXPECT_NEAR(time(), 0.5, 1e-4);

    // Scrubbing: a click at three quarters of the time slider's 0..2 s is 1.5 s and pauses the player.
    const ControlRect slider = h.rect("animation.time");
    h.clickAt(slider.x + slider.w * 0.75f, slider.centerY());
    EXPECT_FALSE(h.state().timeline.playing);
    EXPECT_NEAR(time(), 1.5, 0.05);
    h.frame();
    EXPECT_NEAR(mover().z, 4.0 * (time() - 1.0), 1e-3) << "Move's second leg at the scrubbed time";

    // A saved preset records the animation and the time.
    h.click("preset.saveAs");
    h.selectAllAndType("posed");
    const PresetLoadResult saved = loadPresetFile((folder / "user-presets" / "posed.json").string());
    ASSERT_TRUE(saved.settings) << saved.errors.front();
    EXPECT_EQ(saved.settings->animation.play, "Move");
    EXPECT_FLOAT_EQ(saved.settings->animation.time, h.state().settings.animation.time);
}

// The Stats panel's views table while the scene plays: the change to shadow.update cachedStatic draws the light's view
// in full (its cached static depth is built); with only the Spinner moving ("Spin") it is drawn static + dynamic (the
// cached depth and the Spinner over it) and says the Spinner moved; paused, a redraw for an overlay reuses it.
TEST_F(EditorTimeline, TheViewsTableShowsEachViewsCacheStateWithItsReason) {
    EditorHarness& h = *harness;
    h.click("animation.play");
    h.click("animation.play=Spin");
    h.click("shadow.update");
    h.click("shadow.update=cachedStatic");
    ASSERT_EQ(h.state().settings.lights[0].shadow.update, ShadowUpdate::CachedStatic);
    ASSERT_TRUE(h.reveal("stats.views"));
    auto firstRow = [&] {
        const std::vector<ViewRow> rows = viewRows(h.state().stats, h.state().viewMilliseconds);
        return rows.empty() ? ViewRow{} : rows.front();
    };
    h.settle();
    EXPECT_EQ(firstRow().update, "full");
    EXPECT_EQ(firstRow().why, "shadow.update changed");
    h.click("timeline.play");
    play(0.5);
    EXPECT_EQ(firstRow().update, "static + dynamic") << firstRow().why;
    EXPECT_EQ(firstRow().why, "Spinner moved");
    h.saveWindow("views_table_static_dynamic");
    h.click("timeline.play");  // pause
    h.settle();
    h.click("viewport.frustum");  // a redraw that changes no shadow
    h.frame(2);
    EXPECT_EQ(firstRow().update, "reused") << firstRow().why;
}

// The Outliner's static box: the Spinner, which Spin moves, shows dynamic; ticking it writes casters.static (a static
// flag on something that moves: the frame then warns and the cache is wrong), unticking it removes the path again; the
// Floor, static by the rule, unticked goes to casters.dynamic. The views table follows: a static Spinner leaves the
// view reused while Spin plays.
TEST_F(EditorTimeline, TheOutlinersStaticBoxForcesANodeStaticOrDynamic) {
    EditorHarness& h = *harness;
    h.click("animation.play");
    h.click("animation.play=Spin");
    h.click("shadow.update");
    h.click("shadow.update=cachedStatic");
    const Scene& scene = *h.state().scene;
    auto pathOf = [&](const std::string& name) {
        for (const SceneNode& n : scene.nodes)
            if (n.name == name) return n.path;
        ADD_FAILURE() << "no node " << name;
        return std::string();
    };
    const std::string spinner = pathOf("Spinner"), floor = pathOf("Floor");
    ASSERT_TRUE(h.reveal("outliner.static=" + spinner));
    const CasterSettings& casters = h.state().settings.casters;
    h.click("outliner.static=" + spinner);  // was dynamic (Spin moves it): now forced static
    h.frame(2);
    EXPECT_EQ(casters.forcedStatic, std::vector<std::string>{spinner});
    EXPECT_TRUE(casters.forcedDynamic.empty());
    h.settle();
    h.click("timeline.play");
    play(0.5);
    const std::vector<ViewRow> rows = viewRows(h.state().stats, h.state().viewMilliseconds);
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(rows.front().update, "reused") << "a static Spinner is in the cached depth: " << rows.front().why;
    h.click("timeline.play");  // pause
    h.click("outliner.static=" + spinner);  // back to the rule: no override left
    h.frame(2);
    EXPECT_TRUE(casters.forcedStatic.empty());
    EXPECT_TRUE(casters.forcedDynamic.empty());
    ASSERT_TRUE(h.reveal("outliner.static=" + floor));
    h.click("outliner.static=" + floor);  // static by the rule: now forced dynamic
    h.frame(2);
    EXPECT_EQ(casters.forcedDynamic, std::vector<std::string>{floor});
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings));
    h.saveWindow("outliner-static-boxes");
}

}  // namespace shadowlab::editor::test
