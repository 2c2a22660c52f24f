#include "editor_harness.h"

#include "context/headless_context.h"
#include "editor/editor_style.h"
#include "gl/gl_errors.h"
#include "image/image_io.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <utility>

namespace shadowlab::editor::test {

namespace fs = std::filesystem;

namespace {

HeadlessContext& sharedContext() {
    static HeadlessContext context(/*debug=*/true);
    static bool debugInstalled = (gl::enableDebugOutput(), true);
    (void)debugInstalled;
    return context;
}

// GLFW's key codes for the keys ImGui's widgets use (ImGui 1.86 looks them up through io.KeyMap).
constexpr int kGlfwTab = 258, kGlfwLeft = 263, kGlfwRight = 262, kGlfwUp = 265, kGlfwDown = 264, kGlfwPageUp = 266,
              kGlfwPageDown = 267, kGlfwHome = 268, kGlfwEnd = 269, kGlfwInsert = 260, kGlfwDelete = 261,
              kGlfwBackspace = 259, kGlfwSpace = 32, kGlfwEnter = 257, kGlfwEscape = 256, kGlfwKpEnter = 335;

}  // namespace

fs::path testFolder(const std::string& name) {
    const fs::path folder = fs::path(SHADOWLAB_TEST_OUTPUT) / "editor" / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

EditorOptions testOptions(const fs::path& folder) {
    EditorOptions options;
    options.scene = "builtin:textbook";
    options.preset = "default";
    options.shippedPresetsDir = std::string(SHADOWLAB_SOURCE_DIR) + "/presets";
    options.userPresetsDir = (folder / "user-presets").string();
    options.recentFilesPath = (folder / "recent-files.json").string();
    options.screenshotDir = (folder / "screenshots").string();
    options.autosavePath = (folder / "autosave.json").string();  // never the user's own
    return options;
}

EditorHarness::EditorHarness(const EditorOptions& options, int width, int height) : width_(width), height_(height) {
    sharedContext().makeCurrent();
    gl::takeDebugErrors();
    gl::drainErrors();

    imguiContext_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // tests start from the first-run layout every time
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DeltaTime = 1.0f / 60.0f;
    const int map[][2] = {{ImGuiKey_Tab, kGlfwTab},         {ImGuiKey_LeftArrow, kGlfwLeft},
                          {ImGuiKey_RightArrow, kGlfwRight}, {ImGuiKey_UpArrow, kGlfwUp},
                          {ImGuiKey_DownArrow, kGlfwDown},   {ImGuiKey_PageUp, kGlfwPageUp},
                          {ImGuiKey_PageDown, kGlfwPageDown}, {ImGuiKey_Home, kGlfwHome},
                          {ImGuiKey_End, kGlfwEnd},          {ImGuiKey_Insert, kGlfwInsert},
                          {ImGuiKey_Delete, kGlfwDelete},    {ImGuiKey_Backspace, kGlfwBackspace},
                          {ImGuiKey_Space, kGlfwSpace},      {ImGuiKey_Enter, kGlfwEnter},
                          {ImGuiKey_Escape, kGlfwEscape},    {ImGuiKey_KeyPadEnter, kGlfwKpEnter},
                          {ImGuiKey_A, 'A'}, {ImGuiKey_C, 'C'}, {ImGuiKey_V, 'V'}, {ImGuiKey_X, 'X'},
                          {ImGuiKey_Y, 'Y'}, {ImGuiKey_Z, 'Z'}};
    for (const auto& [imguiKey, code] : map) io.KeyMap[imguiKey] = code;
    applyEditorStyle();
    EXPECT_TRUE(ImGui_ImplOpenGL3_Init("#version 450 core"));

    EXPECT_EQ(window_.resize(width, height), "");

    EditorOptions hooked = options;
    hooked.clock = [this] { return clock_; };
    hooked.wake = [this] {
        std::lock_guard<std::mutex> lock(wakeMutex_);
        ++wakes_;
        ++wakesPosted_;
        wakeSignal_.notify_all();
    };
    editor_ = std::make_unique<Editor>(hooked);
}

EditorHarness::~EditorHarness() {
    // The editor's programs die with it, but one left current (the main pass's, when no overlay drew after it) stays
    // alive until unbound; the next test's ImGui backend would then restore that dead name (GL_INVALID_VALUE).
    glUseProgram(0);
    editor_.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(static_cast<ImGuiContext*>(imguiContext_));
    for (const std::string& e : gl::takeDebugErrors()) ADD_FAILURE() << "GL debug error: " << e;
}

void EditorHarness::frame(int count) {
    for (int i = 0; i < count; ++i) {
        editor_->renderFrame();
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        editor_->buildUi();
        ImGui::Render();
        glBindFramebuffer(GL_FRAMEBUFFER, window_.framebuffer());
        glViewport(0, 0, width_, height_);
        glClearColor(0.09f, 0.09f, 0.10f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        // The IO is per frame: a wheel turn is seen once.
        ImGui::GetIO().MouseWheel = 0.0f;
        ++framesDrawn_;
    }
}

bool EditorHarness::workerRunning() const {
    const EditorState& s = state();
    return s.accuracy.running || s.accuracy.liveRunning || s.sweep.running || s.loading;
}

bool EditorHarness::framesUntil(const std::function<bool()>& done, const std::string& what, double ceilingSeconds) {
    const auto start = std::chrono::steady_clock::now();
    long wakesSeen = 0;
    {
        std::lock_guard<std::mutex> lock(wakeMutex_);
        wakesSeen = wakesPosted_;
    }
    while (!done()) {
        const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (waited > ceilingSeconds) {
            ADD_FAILURE() << "waited " << waited << " s (the ceiling) for " << what << "; it did not happen";
            return false;
        }
        if (workerRunning()) {
            std::unique_lock<std::mutex> lock(wakeMutex_);
            wakeSignal_.wait_for(lock, std::chrono::milliseconds(kWorkerFrameMs),
                                 [&] { return wakesPosted_ != wakesSeen; });
            wakesSeen = wakesPosted_;
        }
        frame();
    }
    return true;
}

int EditorHarness::waitForAccuracyJob(const std::function<void(const AccuracyState&)>& eachFrame) {
    int frames = 0;
    framesUntil(
        [&] {
            const AccuracyState& a = state().accuracy;
            if (frames > 0 && eachFrame && a.running) eachFrame(a);
            ++frames;
            return !a.running;
        },
        "the accuracy job (" + state().accuracy.stage + ") to finish");
    frame(2);
    return frames - 1;
}

void EditorHarness::waitForAutoMeasurements(long count) {
    const AccuracyState& a = state().accuracy;
    framesUntil(
        [&] {
            advanceClock(1.0 / 60.0);
            return a.measurements >= count && !a.running && !a.liveRunning;
        },
        "Auto's full measurement " + std::to_string(count));
    frame(2);
}

int EditorHarness::hostFrames(double seconds) {
    const double end = clock_ + seconds;
    int frames = 0;
    while (clock_ < end) {
        const std::optional<double> wait = editor_->secondsUntilNextFrame();
        if (takeWakes() == 0) {
            if (!wait) break;  // asleep until input: nothing more happens in this stretch
            // A busy host draws at the display's rate (vsync): a 60 Hz frame.
            clock_ = std::min(end, clock_ + std::max(*wait, 1.0 / 60.0));
            if (clock_ >= end) break;
        }
        frame();
        ++frames;
    }
    clock_ = std::max(clock_, end);
    return frames;
}

int EditorHarness::takeWakes() {
    std::lock_guard<std::mutex> lock(wakeMutex_);
    return std::exchange(wakes_, 0);
}

bool EditorHarness::waitForWake(const std::string& what, double ceilingSeconds) {
    std::unique_lock<std::mutex> lock(wakeMutex_);
    if (!wakeSignal_.wait_for(lock, std::chrono::duration<double>(ceilingSeconds), [this] { return wakes_ > 0; })) {
        ADD_FAILURE() << "no wake was posted in " << ceilingSeconds << " s while waiting for " << what;
        return false;
    }
    wakes_ = 0;
    return true;
}

void EditorHarness::settle(int maxFrames) {
    for (int i = 0; i < maxFrames; ++i) {
        frame();
        if (state().scene && !state().loading && !editor_->busy()) {
            frame(2);
            takeWakes();  // a host's frames have answered every wake posted so far
            return;
        }
    }
    ADD_FAILURE() << "the editor did not settle in " << maxFrames << " frames";
}

void EditorHarness::moveMouse(float x, float y) {
    ImGui::GetIO().MousePos = ImVec2(x, y);
    frame();
}

void EditorHarness::clickAt(float x, float y, int button) {
    moveMouse(x, y);
    ImGui::GetIO().MouseDown[button] = true;
    frame();
    ImGui::GetIO().MouseDown[button] = false;
    frame(2);
}

void EditorHarness::click(const std::string& control, int button) {
    const ControlRect r = rect(control);
    clickAt(r.centerX(), r.centerY(), button);
}

void EditorHarness::ctrlClick(const std::string& control) {
    setKey(keys::kLeftControl, true);
    click(control);
    setKey(keys::kLeftControl, false);
    frame();
}

void EditorHarness::drag(const std::string& control, float dx, float dy, int button, int steps, bool shift) {
    const ControlRect r = rect(control);
    if (shift) setKey(keys::kLeftShift, true);
    moveMouse(r.centerX(), r.centerY());
    ImGui::GetIO().MouseDown[button] = true;
    frame();
    for (int i = 1; i <= steps; ++i) moveMouse(r.centerX() + dx * float(i) / float(steps), r.centerY() + dy * float(i) / float(steps));
    ImGui::GetIO().MouseDown[button] = false;
    frame(2);
    if (shift) setKey(keys::kLeftShift, false);
}

void EditorHarness::wheel(const std::string& control, float steps) {
    const ControlRect r = rect(control);
    moveMouse(r.centerX(), r.centerY());
    ImGui::GetIO().MouseWheel = steps;
    frame(2);
}

void EditorHarness::setKey(int key, bool down) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeysDown[key] = down;
    io.KeyCtrl = io.KeysDown[keys::kLeftControl];
    io.KeyShift = io.KeysDown[keys::kLeftShift];
    io.KeyAlt = io.KeysDown[keys::kLeftAlt];
}

void EditorHarness::pressKey(int key, bool ctrl, bool shift) {
    if (ctrl) setKey(keys::kLeftControl, true);
    if (shift) setKey(keys::kLeftShift, true);
    setKey(key, true);
    frame();
    setKey(key, false);
    frame();
    if (ctrl) setKey(keys::kLeftControl, false);
    if (shift) setKey(keys::kLeftShift, false);
    frame();
}

void EditorHarness::typeText(const std::string& text) {
    ImGui::GetIO().AddInputCharactersUTF8(text.c_str());
    frame();
}

void EditorHarness::selectAllAndType(const std::string& text) {
    pressKey('A', /*ctrl=*/true);
    typeText(text);
    pressKey(kGlfwEnter);
}

bool EditorHarness::reveal(const std::string& name) {
    if (hasControl(name)) return true;
    // As a user would: try one sidebar's tabs until the control shows; a sidebar that does not have it goes back to
    // the tab it showed (so a panel open on the other side stays open).
    for (const bool left : {true, false}) {
        std::vector<std::string> tabs;
        std::string open;
        for (const auto& [control, r] : state().controls.all()) {
            if ((r.x < float(width_) * 0.5f) != left) continue;
            if (control.rfind("tab:", 0) == 0) tabs.push_back(control);
            if (control.rfind("tabOpen:", 0) == 0) open = "tab:" + control.substr(8);
        }
        for (const std::string& tab : tabs) {
            const ControlRect* r = state().controls.find(tab);
            if (!r) continue;
            clickAt(r->centerX(), r->centerY());
            if (hasControl(name)) return true;
        }
        if (const ControlRect* r = state().controls.find(open)) clickAt(r->centerX(), r->centerY());
    }
    return false;
}

ControlRect EditorHarness::rect(const std::string& name) {
    reveal(name);
    const ControlRect* r = state().controls.find(name);
    if (!r) {
        ADD_FAILURE() << "control " << name << " was not drawn";
        return {};
    }
    return *r;
}

std::vector<std::uint8_t> EditorHarness::readWindow() const {
    std::vector<std::uint8_t> rgba(std::size_t(width_) * height_ * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(window_.colorTexture(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
    // GL rows are bottom first; callers think top first.
    std::vector<std::uint8_t> flipped(rgba.size());
    const std::size_t row = std::size_t(width_) * 4;
    for (int y = 0; y < height_; ++y)
        std::copy_n(rgba.begin() + std::ptrdiff_t(row * (height_ - 1 - y)), row, flipped.begin() + std::ptrdiff_t(row * y));
    return flipped;
}

std::string EditorHarness::saveWindow(const std::string& name) const {
    const fs::path folder = fs::path(SHADOWLAB_TEST_OUTPUT) / "editor";
    fs::create_directories(folder);
    const std::string path = (folder / (name + ".png")).string();
    std::vector<std::uint8_t> rgba = readWindow();
    for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    EXPECT_EQ(writePng(path, width_, height_, 4, rgba.data(), false), "");
    return path;
}

double variedFraction(const std::vector<std::uint8_t>& rgba, int width, int x0, int y0, int w, int h) {
    const std::uint8_t* first = &rgba[(std::size_t(y0) * width + x0) * 4];
    long differing = 0;
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) {
            const std::uint8_t* p = &rgba[(std::size_t(y) * width + x) * 4];
            differing += std::abs(p[0] - first[0]) + std::abs(p[1] - first[1]) + std::abs(p[2] - first[2]) > 6;
        }
    return double(differing) / double(std::max(1, w * h));
}

}  // namespace shadowlab::editor::test
