#pragma once
// The editor built headless: one EGL context (no X) per test process, an ImGui context per test drawn by ImGui's
// OpenGL3 backend into an FBO the size of a window, and input sent only through ImGui's IO (mouse position and
// buttons, wheel, keys, typed characters) at the real rectangles the widgets were drawn at.
#include "editor/editor.h"
#include "editor/editor_keys.h"
#include "frame/render_target.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab::editor::test {

// A fresh folder under the build's test output for one test (user presets, screenshots).
std::filesystem::path testFolder(const std::string& name);

// Options for a test editor: textbook scene, "default" preset, user presets, screenshots, recent files and the
// autosave in `folder`.
EditorOptions testOptions(const std::filesystem::path& folder);

class EditorHarness {
public:
    explicit EditorHarness(const EditorOptions& options, int width = 1600, int height = 900);
    ~EditorHarness();

    // One frame as a host draws it: renderFrame, NewFrame, buildUi, Render, draw into the window FBO.
    void frame(int count = 1);
    // Frames until the scene has loaded and nothing is pending (fails the test after `maxFrames`).
    void settle(int maxFrames = 600);

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
    RenderTarget window_;  // the window the UI is drawn into
    void* imguiContext_ = nullptr;
    std::unique_ptr<Editor> editor_;
};

// Fraction of pixels in a rectangle (RGBA, top row first) that differ from its first pixel.
double variedFraction(const std::vector<std::uint8_t>& rgba, int width, int x0, int y0, int w, int h);

}  // namespace shadowlab::editor::test
