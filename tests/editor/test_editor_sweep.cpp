// The Cost vs accuracy window, driven through ImGui's IO like a user: opened from the Accuracy panel, a bad axis value
// is refused before any work naming its key, Run sweeps this view on a worker while UI frames keep coming, the chart
// fills in, hovering a point finds it, clicking it applies its values (the preset shows *) and the ring follows.
#include "editor_harness.h"
#include "sweep/sweep_output.h"


namespace shadowlab::editor::test {

TEST(EditorSweep, RunHoverAndApplyAPoint) {
    EditorHarness h(testOptions(testFolder("sweep")), 1280, 720);
    h.settle();
    SweepPanelState& s = h.state().sweep;
    EXPECT_FALSE(h.hasControl("sweep.run"));
    h.click("accuracy.costVsAccuracy");
    h.frame(2);
    ASSERT_TRUE(h.reveal("sweep.run"));

    // A value the key table refuses: nothing starts, the message names the key.
    h.click("sweep.values0");
    h.selectAllAndType("512,7");
    h.click("sweep.run");
    EXPECT_FALSE(s.running);
    EXPECT_NE(s.error.find("shadow.resolution"), std::string::npos) << s.error;

    h.click("sweep.values0");
    h.selectAllAndType("256,1024");
    h.click("sweep.values1");
    h.selectAllAndType("point,pcf");
    h.click("sweep.run");
    EXPECT_TRUE(s.running) << s.error;
    // The host redraws a running sweep's progress on a timer (Editor::secondsUntilNextFrame); the test's frames come
    // at the harness's worker rate (kWorkerFrameMs): on llvmpipe a UI drawing much faster starves the sweep's GL
    // context (its first point's frames then take seconds each).
    const std::optional<double> hostWait = h.editor().secondsUntilNextFrame();
    ASSERT_TRUE(hostWait.has_value()) << "a running sweep's progress is redrawn on a timer";
    h.takeWakes();
    const long framesBefore = h.framesDrawn();
    h.framesUntil([&] { return !s.running; }, "the sweep to finish");
    const long framesDuring = h.framesDrawn() - framesBefore;
    const int wakes = h.takeWakes();  // the sweep's thread woke the host for each point and at its end
    h.frame(2);
    EXPECT_GE(framesDuring, 1) << "the UI keeps drawing while the sweep runs";
    ASSERT_TRUE(s.result.has_value());
    ASSERT_TRUE(s.result->ok) << s.result->error;
    ASSERT_EQ(s.result->points.size(), 4u);
    ASSERT_TRUE(s.result->preset.has_value()) << "the default preset (2048 pcf) is not on these axes: measured too";
    EXPECT_GE(wakes, int(s.result->points.size()) + 2) << "a wake per point, the preset's point and the end";
    const ControlRect view = h.rect("viewport.image");
    EXPECT_EQ(s.result->width, int(view.w)) << "the sweep measures this view";
    EXPECT_GT(s.result->points[0].accuracy.wrongPercent, s.result->points[2].accuracy.wrongPercent)
        << "256² point sampling is more wrong than 1024²";
    h.saveWindow("sweep-window");

    // Hover the 1024 point marker, then click it.
    const ControlRect chart = h.rect("sweep.chart");
    const PlotFrame frame = plotFrame(sweepChart(*s.result), s.chartWidth, s.chartHeight);
    const SweepPointResult& target = s.result->points[2];
    ASSERT_EQ(target.label, "1024 point");
    const float x = chart.x + float(frame.px(target.costMs)), y = chart.y + float(frame.py(target.accuracy.wrongPercent));
    h.moveMouse(x, y);
    h.frame(2);
    ASSERT_TRUE(s.hovered.has_value());
    EXPECT_EQ(*s.hovered, 2u);
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
    h.clickAt(x, y);
    h.frame(2);
    EXPECT_EQ(h.state().settings.lights[0].shadow.resolution, 1024);
    EXPECT_EQ(h.state().settings.filter.kind, FilterKind::Point);
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings)) << "applied values mark the preset *";
    EXPECT_EQ(s.chartMarker, 2u) << "the ring moved to the applied point";
    h.saveWindow("sweep-window-applied");
}

}  // namespace shadowlab::editor::test
