// Issue 19: text cut at 1600x900 where the first-run layout test never looked — the panels as they are with several
// lights of every type (each selected in turn), a probed pixel, a measurement and a bias search's table. Every tab is
// opened in each state and nothing in any panel may be clipped (cutContent, the layout test's check).
#include "editor_harness.h"

#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"


namespace shadowlab::editor::test {

std::vector<std::string> cutContent();  // test_editor_panels.cpp

namespace {

// Every tab of both sidebars opened as a user would; what is cut in each, named by `when`.
void expectNothingCut(EditorHarness& h, const std::string& when) {
    for (const Sidebar side : {Sidebar::Left, Sidebar::Right})
        for (const std::string& tab : sidebarTabs(side)) {
            h.click("tab:" + tab);
            h.frame(2);
            for (const std::string& cut : cutContent()) ADD_FAILURE() << when << ", tab " << tab << ": " << cut;
        }
}

}  // namespace

TEST(EditorLayoutIssue19, EveryPanelIsWholeAt1600x900WithEveryLightTypeAProbeAndABiasSearch) {
    EditorOptions options = testOptions(testFolder("layout-issue19"));
    options.scene = "builtin:courtyard";  // a directional light, two spots and a point light
    options.preset = "courtyard";
    EditorHarness h(options, 1600, 900);
    h.settle();
    const std::size_t lights = h.state().settings.lights.size();
    ASSERT_GE(lights, 3u);
    for (std::size_t light = 0; light < lights; ++light) {
        h.click("lights.select." + std::to_string(light));
        h.frame(2);
        expectNothingCut(h, "light " + std::to_string(light) + " (" + lightTypeText(h.state().settings, light) +
                                ") selected");
    }
    // A probed pixel: the Probe panel's header and lines.
    h.click("lights.select.0");
    const ImVec4 view = h.editor().viewportRect();
    h.clickAt(view.x + view.z * 0.5f, view.y + view.w * 0.6f);
    h.frame(2);
    ASSERT_TRUE(h.state().probe.report.has_value());
    expectNothingCut(h, "a probed pixel");
    // A measurement, then a bias search's table (a few rows are enough: then it is cancelled).
    h.click("accuracy.measure");
    h.waitForAccuracyJob();
    ASSERT_TRUE(h.state().accuracy.report.has_value()) << h.state().accuracy.error;
    expectNothingCut(h, "a measurement");
    h.click("accuracy.suggest");
    h.framesUntil([&] { return !h.state().accuracy.running || h.state().accuracy.steps.size() >= 3; },
                  "the bias search to list 3 rows");
    ASSERT_GE(h.state().accuracy.steps.size(), 3u) << h.state().accuracy.error;
    for (const std::string tab : {"numbers", "causes", "counts", "cost", "search", "flicker"}) {
        h.click("accuracy.tab." + tab);
        h.frame(2);
        for (const std::string& cut : cutContent()) ADD_FAILURE() << "a bias search, Accuracy " << tab << ": " << cut;
        if (tab == std::string("search")) h.saveWindow("layout-issue19-search");
    }
    h.click("accuracy.cancel");
    h.waitForAccuracyJob();
    h.saveWindow("layout-issue19-1600x900");
}

}  // namespace shadowlab::editor::test
