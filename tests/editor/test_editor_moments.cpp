// Issue 21 in the editor, driven through ImGui's IO: the filter combo offers every technique and shows only the
// chosen one's keys; the Shadow map viewer shows a moments technique's stored moments, one channel at a time, its
// range and view named; the soft overlay colours light bleeding and over-darkening against the soft reference with
// its legend and counts; the Probe panel explains a moments lookup (the CLI's description) and stays whole.
#include "editor_harness.h"

#include "accuracy/accuracy_overlay.h"
#include "probe/probe_description.h"
#include "shading/filters/filter_technique.h"

#include <algorithm>
#include <set>

namespace shadowlab::editor::test {

std::vector<std::string> cutContent();  // test_editor_panels.cpp

namespace {

void chooseTechnique(EditorHarness& h, const std::string& name) {
    ASSERT_TRUE(h.reveal("filter.kind"));
    h.click("filter.kind");
    ASSERT_TRUE(h.hasControl("filter.kind=" + name)) << "the combo offers " << name;
    h.click("filter.kind=" + name);
    h.frame(2);
}

}  // namespace

TEST(EditorMoments, TheFilterComboOffersEveryTechniqueAndShowsOnlyTheChosenOnesKeys) {
    EditorHarness h(testOptions(testFolder("EditorMomentsCombo")), 1600, 900);
    h.settle();
    std::set<std::string> everyKey;
    for (const FilterTechnique* t : filterTechniques()) everyKey.insert(t->keys.begin(), t->keys.end());
    ASSERT_TRUE(everyKey.count("filter.bleedReduction") && everyKey.count("filter.momentBias"));
    for (const FilterTechnique* t : filterTechniques()) {
        SCOPED_TRACE(t->name);
        chooseTechnique(h, t->name);
        EXPECT_EQ(h.state().settings.filter.kind, t->kind);
        const std::set<std::string> own(t->keys.begin(), t->keys.end());
        for (const std::string& key : everyKey)
            if (own.count(key))
                EXPECT_TRUE(h.reveal(key)) << key << " is " << t->name << "'s key: shown";
            else
                EXPECT_FALSE(h.hasControl(key)) << key << " is not " << t->name << "'s key: hidden";
    }
    // A chosen technique's key takes a typed value (Ctrl+click turns the slider into a text field).
    chooseTechnique(h, "vsm");
    h.ctrlClick("filter.bleedReduction");
    h.selectAllAndType("0.3");
    EXPECT_FLOAT_EQ(h.state().settings.filter.bleedReduction, 0.3f);
    // Its mips: a checkbox (filter.momentMips), and the Stats panel's mips cost line follows.
    ASSERT_TRUE(h.reveal("filter.momentMips"));
    h.click("filter.momentMips");
    h.frame(2);
    EXPECT_TRUE(h.state().settings.filter.momentMips);
    EXPECT_TRUE(h.state().stats.mipsPass.ran) << h.state().stats.mipsPass.reason;
}

TEST(EditorMoments, TheMapViewerShowsEachStoredMomentWithItsRangeLightAndView) {
    EditorHarness h(testOptions(testFolder("EditorMomentsViewer")), 1600, 900);
    h.settle();
    h.click("shadow.resolution=512");  // a small map: the test reads all of it back
    chooseTechnique(h, "vsm");
    ASSERT_TRUE(h.reveal("viewer.channel")) << "a moments technique offers its moments in the viewer";
    const MapViewerState& v = h.state().viewer;
    EXPECT_EQ(v.options.channel, 0);
    h.click("viewer.channel");
    EXPECT_TRUE(h.hasControl("viewer.channel=moment 2"));
    EXPECT_FALSE(h.hasControl("viewer.channel=moment 3")) << "VSM stores two moments";
    h.click("viewer.channel=moment 2");
    h.frame(3);
    ASSERT_EQ(v.options.channel, 2);
    ASSERT_TRUE(v.error.empty()) << v.error;

    // The range is the channel's least and greatest stored value over the view's layer (auto contrast).
    const ShadowViewStats* shown = h.state().shownView();
    ASSERT_NE(shown, nullptr);
    const int res = shown->resolution;
    ASSERT_EQ(res, 512);
    const std::vector<glm::vec4> moments =
        h.editor().renderer().viewMoments({shown->light, shown->kind, shown->index}, 0, 0, res, res);
    ASSERT_EQ(moments.size(), std::size_t(res) * res);
    float low = moments[0].y, high = moments[0].y;
    for (const glm::vec4& m : moments) low = std::min(low, m.y), high = std::max(high, m.y);
    EXPECT_LT(low, high);
    EXPECT_FLOAT_EQ(v.shown.min, low);
    EXPECT_FLOAT_EQ(v.shown.max, high);
    // Labelled: the light, the view, the channel and that range.
    EXPECT_NE(v.shownLabel.find(shown->name + ": moment 2 of vsm"), std::string::npos) << v.shownLabel;
    char range[80];
    std::snprintf(range, sizeof range, "black %.4g .. white %.4g", double(low), double(high));
    EXPECT_NE(v.shownLabel.find(range), std::string::npos) << v.shownLabel;
    // The picture is that channel: its grey follows z² (the floor's far texels brighter than the casters' near ones).
    const std::vector<std::uint8_t> window = h.readWindow();
    const ControlRect image = h.rect("viewer.image");
    EXPECT_GT(variedFraction(window, h.width(), int(image.x), int(image.y), int(image.w), int(image.h)), 0.05);
    h.saveWindow("viewer-vsm-moment2");
    // Hovering names the stored moments under the cursor.
    h.moveMouse(image.x + image.w * 0.5f, image.y + image.h * 0.5f);
    h.frame(2);
    ASSERT_TRUE(v.hoverTexel.has_value());
    ASSERT_TRUE(v.hoverMoments.has_value());
    const glm::vec4 at = moments[std::size_t(v.hoverTexel->y) * res + std::size_t(v.hoverTexel->x)];
    EXPECT_EQ(*v.hoverMoments, at);

    // MSM stores four; a depth technique none: the choice goes away and the depth is shown again.
    chooseTechnique(h, "msm");
    h.click("viewer.channel");
    EXPECT_TRUE(h.hasControl("viewer.channel=moment 4"));
    h.click("viewer.channel=moment 4");
    h.frame(3);
    EXPECT_EQ(v.options.channel, 4);
    EXPECT_TRUE(v.error.empty()) << v.error;
    EXPECT_NE(v.shownLabel.find("moment 4 of msm"), std::string::npos) << v.shownLabel;
    chooseTechnique(h, "pcf");
    h.click("tab:Map");
    h.frame(2);
    EXPECT_FALSE(h.hasControl("viewer.channel"));
    EXPECT_EQ(v.options.channel, 0);
    EXPECT_TRUE(v.error.empty()) << v.error;
}

TEST(EditorMoments, TheSoftOverlayColoursBleedingAndOverDarkeningWithItsLegendAndCounts) {
    EditorHarness h(testOptions(testFolder("EditorMomentsSoftOverlay")), 1280, 720);
    h.settle();
    chooseTechnique(h, "vsm");
    ASSERT_TRUE(h.state().edit("reference.softRays", 64));
    h.click("view");
    ASSERT_TRUE(h.hasControl("view=soft overlay")) << "the view combo offers the soft overlay";
    h.click("view=soft overlay");
    const AccuracyState& a = h.state().accuracy;
    EXPECT_EQ(a.overlayKind, OverlayKind::Soft);

    // A hard light has no soft reference: the view says so instead of showing another overlay.
    h.click("accuracy.measure");
    h.waitForAccuracyJob();
    ASSERT_TRUE(a.report && a.report->ok) << a.error;
    h.frame(2);
    EXPECT_FALSE(a.overlayShown());
    EXPECT_TRUE(h.hasControl("viewport.overlayNote"));
    EXPECT_FALSE(h.hasControl("viewport.softCounts"));

    // A 2-degree sun: the overlay, its legend and its counts.
    ASSERT_TRUE(h.reveal("light.size"));
    h.ctrlClick("light.size");
    h.selectAllAndType("2");
    h.settle();
    ASSERT_EQ(h.state().settings.lights[0].size, 2.0f);
    h.click("accuracy.measure");
    h.waitForAccuracyJob();
    ASSERT_TRUE(a.report && a.report->ok) << a.error;
    ASSERT_TRUE(a.report->soft.measured);
    h.frame(2);
    EXPECT_TRUE(a.overlayShown());
    EXPECT_EQ(a.uploadedKind, OverlayKind::Soft);
    EXPECT_TRUE(h.hasControl("viewport.legend"));
    EXPECT_TRUE(h.hasControl("viewport.softCounts"));
    const AccuracyReport& r = *a.report;
    const SoftCounts& c = r.soft.counts;
    std::printf("textbook, VSM, 2-degree sun: %s; %zu penumbra pixels\n", softOverlayCounts(r.soft).c_str(),
                c.penumbra);
    EXPECT_GT(c.penumbra, 100u);

    // The view shows the report's soft overlay, pixel for pixel, between the toolbar (two rows over the view's top
    // at 1280x720) and the counts and legend at its foot.
    const std::vector<std::uint8_t> window = h.readWindow();
    h.saveWindow("soft-overlay");
    const ImVec4 view = h.editor().viewportRect();
    ASSERT_EQ(int(view.z), r.width);
    ASSERT_EQ(int(view.w), r.height);
    std::size_t same = 0, compared = 0, penumbra = 0;
    for (int y = r.height / 4; y < r.height / 2; ++y)
        for (int x = 0; x < r.width; ++x) {
            const std::uint8_t* shown = &window[(std::size_t(int(view.y) + y) * h.width() + int(view.x) + x) * 4];
            const std::uint8_t* made = &r.softOverlayRgba[(std::size_t(y) * r.width + x) * 4];
            ++compared;
            same += std::abs(shown[0] - made[0]) <= 2 && std::abs(shown[1] - made[1]) <= 2 &&
                    std::abs(shown[2] - made[2]) <= 2;
            penumbra += isShadeOf(softLegend()[2], shown);
        }
    EXPECT_GT(double(same), 0.99 * double(compared));
    EXPECT_GT(penumbra, 0u) << "the true penumbra is tinted";
}

TEST(EditorMoments, TheProbePanelExplainsAMomentsLookupAsTheCliDoesAndStaysWhole) {
    EditorHarness h(testOptions(testFolder("EditorMomentsProbe")), 1600, 900);
    h.settle();
    chooseTechnique(h, "vsm");
    const ImVec4 view = h.editor().viewportRect();
    h.clickAt(view.x + view.z * 0.5f, view.y + view.w * 0.6f);
    h.frame(2);
    const ProbeState& p = h.state().probe;
    ASSERT_TRUE(p.report.has_value());
    const PixelProbeReport& r = *p.report;
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_TRUE(r.momentLookup);
    EXPECT_TRUE(r.agrees) << "the CPU mirror and the GPU agree";
    // The lines the panel shows are the CLI's (describeProbe): the moments read and the bound in words.
    const std::vector<std::string> lines = describeProbe(r);
    const bool explained = std::any_of(lines.begin(), lines.end(), [&](const std::string& line) {
        return line.find("mean") != std::string::npos && line.find("variance") != std::string::npos &&
               line.find("Chebyshev bound") != std::string::npos;
    });
    EXPECT_TRUE(explained) << "the VSM lookup's mean, variance and bound";
    ASSERT_TRUE(h.reveal("probe.lines"));
    // Whole at 1600x900: the Probe panel and the Map panel showing a moment.
    h.click("tab:Probe");
    h.frame(2);
    for (const std::string& cut : cutContent()) ADD_FAILURE() << "Probe tab: " << cut;
    h.saveWindow("probe-vsm");
    h.click("tab:Map");
    h.click("viewer.channel");
    h.click("viewer.channel=moment 1");
    h.frame(2);
    for (const std::string& cut : cutContent()) ADD_FAILURE() << "Map tab, moment 1: " << cut;
    h.saveWindow("map-vsm-moment1");
}

}  // namespace shadowlab::editor::test
