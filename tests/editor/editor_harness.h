#pragma once
// The editor built headless: one EGL context (no X) per test process, an ImGui context per test drawn by ImGui's
// OpenGL3 backend into an FBO the size of a window, and input sent only through ImGui's IO (mouse position and
// buttons, wheel, keys, typed characters) at the real rectangles the widgets were drawn at.
#include "editor/editor.h"
#include "editor/editor_keys.h"
#include "frame/render_target.h"

#include <gtest/gtest.h>

#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace shadowlab::editor::test {

// A fresh folder under the build's test output for one test (user presets, screenshots).
std::filesystem::path testFolder(const std::string& name);

// Options for a test editor: textbook scene, "default" preset, user presets, screenshots, recent files and the
// autosave in `folder`.
EditorOptions testOptions(const std::filesystem::path& folder);

// How long a test waits, in real time, for something a worker thread does (its speed depends on the machine's load,
// which a test cannot control): a ceiling, never a duration a test expects to take.
constexpr double kWorkerCeilingSeconds = 600.0;
// While a worker runs (accuracy job or live count, sweep, scene load), a test draws a UI frame at most this often: on
// llvmpipe each frame draws the viewport on the cores the worker needs, and a frame every 20 ms made a bias search
// take 60-120 s instead of seconds. A worker's wake (its end, a sweep's point) brings the next frame at once.
constexpr int kWorkerFrameMs = 250;

class EditorHarness {
public:
    // The editor runs on the harness's clock (options.clock is replaced): it starts at 0 and moves only when a test
    // moves it (advanceClock, hostFrames), never with frames or real time, so Auto's delay and the light animation
    // do not depend on the machine's speed. options.wake is replaced by the harness's wake count.
    explicit EditorHarness(const EditorOptions& options, int width = 1600, int height = 900);
    ~EditorHarness();

    // One frame as a host draws it: renderFrame, NewFrame, buildUi, Render, draw into the window FBO.
    void frame(int count = 1);
    // Frames until the scene has loaded and nothing is pending (fails the test after `maxFrames`); the wakes posted
    // so far count as answered.
    void settle(int maxFrames = 600);

    // The editor's injected clock.
    double clock() const { return clock_; }
    void advanceClock(double seconds) { clock_ += seconds; }
    long framesDrawn() const { return framesDrawn_; }
    // Frames until `done()` holds: every wait for a worker goes through it. While a worker runs, a frame per
    // kWorkerFrameMs of real time or per wake, whichever comes first; otherwise frame after frame. Fails the test
    // naming `what` when the real-time ceiling passes first; returns whether `done()` holds.
    bool framesUntil(const std::function<bool()>& done, const std::string& what,
                     double ceilingSeconds = kWorkerCeilingSeconds);
    // Whether a worker of the editor runs: the accuracy job or live count, a sweep, a scene load.
    bool workerRunning() const;
    // The window host's loop (app/editor_window/edit_command.cpp) over `seconds` of the injected clock, with no
    // input: a frame when the editor is busy (1/60 s apart), when its timed wake falls due (the clock jumps there),
    // or when a worker posted a wake; while it would sleep until input, the clock jumps to the end. Returns the
    // frames drawn.
    int hostFrames(double seconds);
    // Frames until the running accuracy job has ended (then two more: its numbers are drawn); `eachFrame` sees the
    // state after every frame built while the job still runs. Returns how many frames were built meanwhile.
    int waitForAccuracyJob(const std::function<void(const AccuracyState&)>& eachFrame = {});
    // Frames until Auto has made `count` full measurements and no job runs, then two more. The injected clock moves a
    // 60 Hz frame's time each frame, so Auto's delay passes as it would for a user looking at a still view.
    void waitForAutoMeasurements(long count);
    // Worker wakes (options.wake) since the last takeWakes; waitForWake blocks in real time until one is posted
    // (fails the test naming `what` at the ceiling).
    int takeWakes();
    bool waitForWake(const std::string& what, double ceilingSeconds = kWorkerCeilingSeconds);

    // Input through ImGui's IO. Each call runs the frames ImGui needs to see it.
    void moveMouse(float x, float y);
    void click(const std::string& control, int button = 0);
    void clickAt(float x, float y, int button = 0);
    void ctrlClick(const std::string& control);
    // Drags from the control's centre (or a point) by (dx, dy) in `steps` moves.
    void drag(const std::string& control, float dx, float dy, int button = 0, int steps = 8, bool shift = false);
    void wheel(const std::string& control, float steps);
    void pressKey(int key, bool ctrl = false, bool shift = false);
    void typeText(const std::string& text);
    void selectAllAndType(const std::string& text);  // Ctrl+A then the text then Enter, in the focused field
    static constexpr int kEnterKey = 257;  // GLFW_KEY_ENTER

    bool hasControl(const std::string& name) const { return state().controls.find(name) != nullptr; }
    // A control's rectangle; a control in a sidebar tab that is not open is shown first by clicking the tabs (as a
    // user would). Fails the test if the control is drawn nowhere.
    ControlRect rect(const std::string& name);
    bool reveal(const std::string& name);  // true once the control is drawn

    // The whole window as drawn (RGBA, top row first) and as a PNG under the test output (look at it).
    std::vector<std::uint8_t> readWindow() const;
    std::string saveWindow(const std::string& name) const;

    Editor& editor() { return *editor_; }
    EditorState& state() { return editor_->state(); }
    const EditorState& state() const { return editor_->state(); }
    int width() const { return width_; }
    int height() const { return height_; }

    // A key held down or let go; the next frame() sees it (pressKey is the whole press).
    void setKey(int key, bool down);

private:
    int width_, height_;
    double clock_ = 0.0;
    long framesDrawn_ = 0;
    std::mutex wakeMutex_;
    std::condition_variable wakeSignal_;
    int wakes_ = 0;
    long wakesPosted_ = 0;  // every wake ever posted (takeWakes does not reset it): framesUntil waits on it
    RenderTarget window_;  // the window the UI is drawn into
    void* imguiContext_ = nullptr;
    std::unique_ptr<Editor> editor_;
};

// Fraction of pixels in a rectangle (RGBA, top row first) that differ from its first pixel.
double variedFraction(const std::vector<std::uint8_t>& rgba, int width, int x0, int y0, int w, int h);

}  // namespace shadowlab::editor::test
