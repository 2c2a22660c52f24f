// An idle editor sleeps: the window host's loop (Editor::secondsUntilNextFrame, replayed by the harness on the
// editor's injected clock) draws no frame while nothing runs or is due, a worker's end wakes it through
// EditorOptions::wake, and Auto's delay wakes it exactly when it falls due.
#include "editor_harness.h"

#include <optional>

namespace shadowlab::editor::test {

TEST(EditorIdle, AnIdleEditorDrawsNoFrameUntilAWorkerWakesIt) {
    EditorHarness h(testOptions(testFolder("idle")), 1280, 720);
    h.settle();
    // Nothing running or due: ten minutes of the editor's clock with no input draw no frame.
    EXPECT_EQ(h.editor().secondsUntilNextFrame(), std::nullopt) << "an idle editor asked for a timed frame";
    EXPECT_EQ(h.hostFrames(600.0), 0);

    // A measurement: its end posts a wake (no timer needed to notice it), and the frame it brings adopts the result.
    h.takeWakes();
    h.click("accuracy.measure");
    ASSERT_TRUE(h.state().accuracy.running);
    ASSERT_TRUE(h.waitForWake("the accuracy job's end"));
    h.frame();
    EXPECT_FALSE(h.state().accuracy.running);
    EXPECT_EQ(h.state().accuracy.measurements, 1) << h.state().accuracy.error;
    // Then idle again: the new numbers drawn, no frame more.
    h.settle();
    EXPECT_EQ(h.hostFrames(600.0), 0);
}

TEST(EditorIdle, AutosDelayWakesTheHostWhenItFallsDue) {
    EditorHarness h(testOptions(testFolder("idle-auto")), 1280, 720);
    h.settle();
    h.click("accuracy.auto");
    // The view is still: the host sleeps until Auto's delay falls due (one frame), then follows the job.
    const std::optional<double> wait = h.editor().secondsUntilNextFrame();
    ASSERT_TRUE(wait.has_value()) << "Auto is due, yet the host would sleep until input";
    EXPECT_LE(*wait, AccuracyState::kAutoDelaySeconds);
    EXPECT_GT(*wait, 0.0);
    h.advanceClock(*wait);
    h.frame();
    EXPECT_TRUE(h.state().accuracy.running) << "Auto's delay fell due and no measurement started";
    h.waitForAccuracyJob();
    EXPECT_EQ(h.state().accuracy.measurements, 1);
    // Measured once: nothing more is due.
    h.settle();
    EXPECT_EQ(h.hostFrames(600.0), 0);
}

}  // namespace shadowlab::editor::test
