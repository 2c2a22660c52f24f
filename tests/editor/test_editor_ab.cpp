// A/B in the editor (issue 13): a snapshot A beside the edited settings B in one split view with a draggable divider;
// editing B never re-renders A; Swap and Apply A move settings between the sides and the preset's "*" follows.
#include "editor_harness.h"

#include "accuracy/compare_label.h"
#include "image/image_io.h"
#include "image/png_text.h"
#include "image/split_view.h"
#include "settings/preset_io.h"

#include <cstdlib>
#include <fstream>
#include <iterator>

namespace shadowlab::editor::test {

namespace {

class EditorAb : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
        harness = std::make_unique<EditorHarness>(testOptions(folder));
        harness->settle();
    }
    void type(const std::string& control, const std::string& text) {
        harness->ctrlClick(control);  // Ctrl+click turns the slider into a text field
        harness->selectAllAndType(text);
        harness->settle();
    }
    // Fraction of the viewport's pixels in columns [x0, x1) of the view (rows in its lower half, below the labels)
    // where the window differs from B's own rendered picture.
    double differsFromB(float x0, float x1) {
        EditorHarness& h = *harness;
        const std::vector<std::uint8_t> window = h.readWindow();
        const RenderTarget& b = h.editor().viewportTarget();
        const std::vector<std::uint8_t> bPixels = b.readColor();  // GL rows: bottom first
        const ImVec4 view = h.editor().viewportRect();
        const int w = b.width(), hh = b.height();
        long differ = 0, total = 0;
        for (int y = hh / 2; y < hh * 9 / 10; ++y)
            for (int x = int(x0); x < int(x1); ++x) {
                const std::size_t wi =
                    (std::size_t(int(view.y) + y) * std::size_t(h.width()) + std::size_t(int(view.x) + x)) * 4;
                const std::size_t bi = (std::size_t(hh - 1 - y) * std::size_t(w) + std::size_t(x)) * 4;
                int d = 0;
                for (std::size_t c = 0; c < 3; ++c)
                    d = std::max(d, std::abs(int(window[wi + c]) - int(bPixels[bi + c])));
                differ += d > 3;
                ++total;
            }
        return total ? double(differ) / double(total) : 0.0;
    }
    // Measure in the Accuracy panel and wait for the numbers.
    void measure() {
        harness->click("accuracy.measure");
        harness->waitForAccuracyJob();
    }
    std::filesystem::path folder;
    std::unique_ptr<EditorHarness> harness;
};

}  // namespace

TEST_F(EditorAb, SnapshotEditDragSwapApply) {
    EditorHarness& h = *harness;
    const AbState& ab = h.state().ab;
    const float savedBias = h.state().settings.lights[0].shadow.depthBias;
    ASSERT_FALSE(h.hasControl("ab.menu"));
    h.click("ab.start");
    h.settle();
    ASSERT_TRUE(ab.active);
    EXPECT_EQ(ab.renders, 1) << "A rendered once for its snapshot";
    EXPECT_TRUE(ab.haveStatsA);
    EXPECT_TRUE(h.reveal("ab.divider"));

    // B: no bias at all (acne over the lit surfaces). A keeps its picture without a pass.
    const long bFrames = h.state().renderedFrames;
    type("shadow.depthBias", "0");
    type("shadow.slopeScaledDepthBias", "0");
    type("shadow.normalOffset", "0");
    ASSERT_EQ(h.state().settings.lights[0].shadow.depthBias, 0.0f);
    EXPECT_GT(h.state().renderedFrames, bFrames) << "B re-rendered for its edits";
    EXPECT_EQ(ab.renders, 1) << "editing B re-rendered A";
    EXPECT_EQ(ab.a.lights[0].shadow.depthBias, savedBias);
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings));

    // The view shows A left of the divider and B right of it.
    const ImVec4 view = h.editor().viewportRect();
    const float split = std::floor(ab.divider * view.z);
    h.saveWindow("ab-split");
    const double leftDiffers = differsFromB(8.0f, split - 8.0f);
    const double rightDiffers = differsFromB(split + 8.0f, view.z - 8.0f);
    EXPECT_GT(leftDiffers, 0.02) << "the left part is not A's picture";
    EXPECT_LT(rightDiffers, 0.001) << "the right part is not B's picture";

    // The divider drags (and the camera stays where it was).
    const glm::dvec3 eye = h.editor().orbitCamera()->eye();
    const float before = ab.divider;
    h.drag("ab.divider", -view.z * 0.25f, 0.0f);
    EXPECT_NEAR(ab.divider, before - 0.25f, 0.02f);
    EXPECT_LT(glm::length(h.editor().orbitCamera()->eye() - eye), 1e-12) << "dragging the divider orbited";
    h.frame(2);
    h.saveWindow("ab-divider-dragged");
    EXPECT_EQ(ab.renders, 1) << "moving the divider re-rendered A";

    // Swap: B is the saved preset again (no "*"), A holds the edit.
    h.click("ab.menu");
    h.click("ab.swap");
    h.settle();
    EXPECT_EQ(h.state().settings.lights[0].shadow.depthBias, savedBias);
    EXPECT_EQ(ab.a.lights[0].shadow.depthBias, 0.0f);
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
    EXPECT_EQ(h.editor().windowTitle().find('*'), std::string::npos) << h.editor().windowTitle();
    EXPECT_EQ(ab.aName, "default *");
    EXPECT_EQ(ab.renders, 2) << "A changed on the swap, so it rendered once more";

    // Apply A: B takes A's settings and is the unsaved edit again.
    h.click("ab.menu");
    h.click("ab.applyA");
    h.settle();
    Settings expected = ab.a;
    expected.view = h.state().settings.view;
    EXPECT_EQ(h.state().settings, expected);
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings));
    EXPECT_NE(h.editor().windowTitle().find('*'), std::string::npos) << h.editor().windowTitle();
    EXPECT_EQ(ab.renders, 2) << "applying A did not change A";

    // Stop: one view, the edited settings stay.
    h.click("ab.menu");
    h.click("ab.stop");
    h.settle();
    EXPECT_FALSE(ab.active);
    EXPECT_FALSE(h.hasControl("ab.divider"));
    EXPECT_EQ(h.state().settings.lights[0].shadow.depthBias, 0.0f);
}

TEST_F(EditorAb, LabelsNameEachSideWithItsTimes) {
    EditorHarness& h = *harness;
    h.click("ab.start");
    h.settle();
    type("shadow.depthBias", "0");
    const std::optional<AccuracyViewKey> now = h.editor().currentView();
    const std::vector<std::string> a = abLabel(h.state(), true, now), b = abLabel(h.state(), false, now);
    ASSERT_GE(a.size(), 2u);
    ASSERT_GE(b.size(), 2u);
    EXPECT_EQ(a[0], "A: default");
    EXPECT_EQ(b[0], "B: default *");
    EXPECT_EQ(a[1].rfind("shadow ", 0), 0u) << a[1];
    EXPECT_NE(a[1].find(" ms, main "), std::string::npos) << a[1];
    EXPECT_NE(b[1].find(" ms, main "), std::string::npos) << b[1];
}

TEST_F(EditorAb, EachSideShowsTheAccuracyMeasuredForIt) {
    harness.reset();
    harness = std::make_unique<EditorHarness>(testOptions(folder), 1280, 720);  // a small view measures quickly
    harness->settle();
    EditorHarness& h = *harness;
    measure();  // the preset's settings: they become A
    ASSERT_TRUE(h.state().accuracy.report.has_value());
    const AccuracyReport reportA = *h.state().accuracy.report;
    const double acneA = reportA.acnePercent;
    h.click("ab.start");
    h.settle();
    type("shadow.depthBias", "0");
    type("shadow.slopeScaledDepthBias", "0");
    type("shadow.normalOffset", "0");
    std::vector<std::string> b = abLabel(h.state(), false, h.editor().currentView());
    EXPECT_EQ(b.size(), 2u) << "B shows numbers measured for other settings";
    measure();
    ASSERT_TRUE(h.state().accuracy.report.has_value());
    const double acneB = h.state().accuracy.report->acnePercent;
    EXPECT_GT(acneB, acneA + 1.0) << "no bias should show acne";
    const std::optional<AccuracyViewKey> now = h.editor().currentView();
    const std::vector<std::string> a = abLabel(h.state(), true, now);
    b = abLabel(h.state(), false, now);
    ASSERT_EQ(a.size(), 3u);
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(a[2], accuracyLine(reportA));
    EXPECT_EQ(b[2], accuracyLine(*h.state().accuracy.report));
    EXPECT_EQ(a[2].rfind("acne ", 0), 0u) << a[2];
    h.saveWindow("ab-accuracy");
    // A moved camera: neither side's numbers describe the view any more. (The divider, at the view's centre where a
    // drag starts, goes aside first.)
    h.drag("ab.divider", -h.editor().viewportRect().z * 0.3f, 0.0f);
    h.drag("viewport.image", 60.0f, 0.0f);
    EXPECT_EQ(abLabel(h.state(), true, h.editor().currentView()).size(), 2u);
    EXPECT_EQ(abLabel(h.state(), false, h.editor().currentView()).size(), 2u);
}

}  // namespace shadowlab::editor::test

namespace shadowlab::editor::test {

// F12 while comparing saves what the view shows: A left of the divider, B right of it, both labelled; the picture
// carries B's preset (the one being edited), and A's under its own keyword.
TEST_F(EditorAb, F12SavesTheSplitPictureWithBothPresets) {
    EditorHarness& h = *harness;
    h.click("ab.start");
    h.settle();
    type("shadow.depthBias", "0");
    type("shadow.slopeScaledDepthBias", "0");
    type("shadow.normalOffset", "0");
    h.pressKey(keys::kF12);
    h.settle();
    std::vector<std::filesystem::path> shots;
    for (const auto& e : std::filesystem::directory_iterator(folder / "screenshots"))
        if (e.path().extension() == ".png") shots.push_back(e.path());
    ASSERT_EQ(shots.size(), 1u);
    const std::optional<PngImage> png = readPng(shots[0].string());
    ASSERT_TRUE(png.has_value());
    const RenderTarget& b = h.editor().viewportTarget();
    ASSERT_EQ(png->width, b.width());
    ASSERT_EQ(png->height, b.height());
    ASSERT_EQ(png->channels, 4);
    // Rows in the lower half (below the labels): left of the divider differs from B's own picture, right equals it.
    const std::vector<std::uint8_t> bTop = topRowFirst(b.readColor(), b.width(), b.height());
    const int split = splitColumn(b.width(), h.state().ab.divider);
    long leftDiffer = 0, rightDiffer = 0, leftTotal = 0, rightTotal = 0;
    for (int y = b.height() / 2; y < b.height() * 9 / 10; ++y)
        for (int x = 4; x < b.width() - 4; ++x) {
            if (std::abs(x - split) < 4) continue;
            const std::size_t i = (std::size_t(y) * std::size_t(b.width()) + std::size_t(x)) * 4;
            int d = 0;
            for (std::size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int(png->pixels[i + c]) - int(bTop[i + c])));
            (x < split ? leftDiffer : rightDiffer) += d > 3;
            ++(x < split ? leftTotal : rightTotal);
        }
    EXPECT_GT(double(leftDiffer) / double(leftTotal), 0.02) << "the left part is not A's picture";
    EXPECT_LT(double(rightDiffer) / double(rightTotal), 0.001) << "the right part is not B's picture";
    // The labels' boxes darken both top corners.
    auto luma = [&](int x, int y) {
        const std::size_t i = (std::size_t(y) * std::size_t(b.width()) + std::size_t(x)) * 4;
        return int(png->pixels[i]) + int(png->pixels[i + 1]) + int(png->pixels[i + 2]);
    };
    EXPECT_LT(luma(12, 12), 150);
    EXPECT_LT(luma(b.width() - 12, 12), 150);
    // B's preset loads back from the picture; A's rides along.
    const PresetLoadResult loaded = loadPresetFile(shots[0].string());
    ASSERT_TRUE(loaded.settings.has_value()) << (loaded.errors.empty() ? "" : loaded.errors.front());
    EXPECT_EQ(loaded.settings->lights[0].shadow.depthBias, 0.0f);
    std::ifstream in(shots[0], std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::optional<std::string> a = findPngText(bytes.data(), bytes.size(), kPresetAPngKeyword);
    ASSERT_TRUE(a.has_value()) << "A's preset is not in the picture";
    const PresetLoadResult loadedA = presetFromText(*a);
    ASSERT_TRUE(loadedA.settings.has_value()) << (loadedA.errors.empty() ? "" : loadedA.errors.front());
    EXPECT_EQ(loadedA.settings->lights[0].shadow.depthBias, h.state().ab.a.lights[0].shadow.depthBias);
    const Message* said = h.state().lastMessage();
    ASSERT_NE(said, nullptr);
    EXPECT_NE(said->text.find("A/B as shown"), std::string::npos) << said->text;
}

}  // namespace shadowlab::editor::test
