// The status line (issue 13): its message is cut at the window's edge, so hovering shows the whole text, and a Log
// button opens the last 50 messages with their times, errors in red.
#include "editor_harness.h"

namespace shadowlab::editor::test {

namespace {

constexpr int kEscape = 256;  // GLFW_KEY_ESCAPE

class EditorStatusLog : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
        harness = std::make_unique<EditorHarness>(testOptions(folder));
        harness->settle();
    }
    // Pixels in a control's rectangle drawn in the log's error red (high red, low green and blue).
    long redPixels(const std::string& control) {
        EditorHarness& h = *harness;
        const ControlRect r = h.rect(control);
        const std::vector<std::uint8_t> window = h.readWindow();
        long red = 0;
        for (int y = int(r.y); y < int(r.y + r.h) && y < h.height(); ++y)
            for (int x = int(r.x); x < int(r.x + r.w) && x < h.width(); ++x) {
                const std::uint8_t* p = &window[(std::size_t(y) * std::size_t(h.width()) + std::size_t(x)) * 4];
                red += p[0] > 180 && p[1] < 140 && p[2] < 140;
            }
        return red;
    }
    std::filesystem::path folder;
    std::unique_ptr<EditorHarness> harness;
};

}  // namespace

TEST_F(EditorStatusLog, HoverShowsTheWholeMessage) {
    EditorHarness& h = *harness;
    std::string longText = "a long message:";
    for (int i = 0; i < 40; ++i) longText += " word" + std::to_string(i);
    longText += " END";
    h.state().say(longText);
    h.frame();
    const ControlRect status = h.rect("status");
    h.moveMouse(status.x + 20.0f, status.centerY());
    h.frame(2);
    ASSERT_TRUE(h.reveal("status.tooltip")) << "no tooltip over the status line";
    const ControlRect tip = h.rect("status.tooltip");
    // The tooltip wraps the text over several lines inside the window (the status line shows one, cut).
    EXPECT_GT(tip.h, 2.5f * ImGui::GetTextLineHeight());
    EXPECT_LE(tip.x + tip.w, float(h.width()));
    h.saveWindow("status-tooltip");
    h.moveMouse(10.0f, 10.0f);
    h.frame(2);
    EXPECT_FALSE(h.hasControl("status.tooltip"));
}

TEST_F(EditorStatusLog, TheLogKeepsTheLast50WithErrorsInRed) {
    EditorHarness& h = *harness;
    for (int i = 0; i < 60; ++i)
        h.state().say("message " + std::to_string(i), /*error=*/i == 57);
    h.frame();
    ASSERT_EQ(h.state().messages.size(), 50u);
    EXPECT_EQ(h.state().messages.front().text, "message 10");
    EXPECT_EQ(h.state().messages.back().clock.size(), 8u) << "HH:MM:SS";
    ASSERT_FALSE(h.hasControl("log"));
    h.click("status.log");
    h.frame(2);
    ASSERT_TRUE(h.reveal("log")) << "the Log button opened nothing";
    EXPECT_TRUE(h.reveal("log.49"));
    EXPECT_FALSE(h.hasControl("log.50"));
    h.saveWindow("message-log");
    // Opened at the newest: the error (message 57, line 47) is in view, in red; its neighbours are not red.
    EXPECT_GT(redPixels("log.47"), 10) << "the error is not red";
    EXPECT_EQ(redPixels("log.48"), 0);
    EXPECT_EQ(redPixels("log.46"), 0);
    h.pressKey(kEscape);
    h.frame(2);
    EXPECT_FALSE(h.hasControl("log")) << "Escape left the log open";
}

}  // namespace shadowlab::editor::test
