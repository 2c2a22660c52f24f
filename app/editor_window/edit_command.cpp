#include "editor_window/edit_command.h"

#include "editor/editor.h"
#include "editor/editor_style.h"
#include "editor_window/key_event_queue.h"
#include "gl/gl.h"
#include "settings/atomic_file.h"
#include "settings/regular_file.h"
#include "settings/user_config.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::editor_window {

namespace {

std::string g_glfwError;

// Everything GLFW's callbacks need, reached through the window's user pointer.
struct Host {
    editor::Editor* editor = nullptr;
    KeyEventQueue keys;
    int framesAfterInput = 3;  // ImGui needs a few frames to settle after an event (hover, popups)
    long buttonEvents = 0;     // mouse presses and releases received
    long keyEvents = 0;        // key presses and releases handed to ImGui
    std::atomic<bool> woken{false};  // a worker has something to show (set on its thread)
};

Host& hostOf(GLFWwindow* window) { return *static_cast<Host*>(glfwGetWindowUserPointer(window)); }

void installCallbacks(GLFWwindow* window) {
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int scancode, int action, int mods) {
        hostOf(w).keys.pushKey(key, scancode, action, mods);
        hostOf(w).framesAfterInput = 3;
    });
    glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int c) {
        hostOf(w).keys.pushChar(c);
        hostOf(w).framesAfterInput = 3;
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
        ImGui_ImplGlfw_MouseButtonCallback(w, button, action, mods);
        ++hostOf(w).buttonEvents;
        hostOf(w).framesAfterInput = 3;
    });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double x, double y) {
        ImGui_ImplGlfw_ScrollCallback(w, x, y);
        hostOf(w).framesAfterInput = 3;
    });
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double, double) { hostOf(w).framesAfterInput = 3; });
    glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int entered) {
        ImGui_ImplGlfw_CursorEnterCallback(w, entered);
        hostOf(w).framesAfterInput = 3;
    });
    glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int focused) {
        ImGui_ImplGlfw_WindowFocusCallback(w, focused);
        hostOf(w).framesAfterInput = 3;
    });
    glfwSetWindowSizeCallback(window, [](GLFWwindow* w, int, int) { hostOf(w).framesAfterInput = 3; });
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
        std::vector<std::string> files(paths, paths + count);
        hostOf(w).editor->dropFiles(files);
        hostOf(w).framesAfterInput = 3;
    });
}

int noWindow(const std::string& why) {
    std::cerr << "shadowlab edit: cannot open the editor window: " << why
              << "\n  The editor needs a display. Without one, use `shadowlab render ...` (headless), or run the "
                 "editor under a virtual display: xvfb-run -s '-screen 0 1920x1080x24' shadowlab edit\n";
    return 1;
}

// Writes the controls' rectangles for scripts when $SHADOWLAB_EDITOR_CONTROLS names a file and they changed, with
// "input": the mouse position the frame just drawn saw and how many mouse-button and key events the window handled
// before it, so a script waits until the editor has seen its input instead of sleeping.
void writeControlsFile(editor::Editor& ed, const Host& host, std::string& lastWritten) {
    static const char* path = std::getenv("SHADOWLAB_EDITOR_CONTROLS");
    if (!path || !*path) return;
    nlohmann::json out = nlohmann::json::parse(ed.state().controls.toJson());
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    out["input"] = {{"mouse", {int(mouse.x), int(mouse.y)}}, {"buttons", host.buttonEvents}, {"keys", host.keyEvents}};
    const std::string json = out.dump(1);
    if (json == lastWritten) return;
    if (writeFileAtomically(path, json).empty()) lastWritten = json;
}

// The panel layout goes through the atomic writer like every other file (ImGui's own save truncates the file
// first, so a full disk would lose it); ImGui asks for a save through WantSaveIniSettings.
void saveLayout(const std::string& iniPath) {
    ImGuiIO& io = ImGui::GetIO();
    io.WantSaveIniSettings = false;
    if (iniPath.empty()) return;
    std::size_t size = 0;
    const char* text = ImGui::SaveIniSettingsToMemory(&size);
    if (std::string error = writeFileAtomically(iniPath, text, size); !error.empty())
        std::cerr << "shadowlab: warning: cannot save the panel layout to " << iniPath << ": " << error << "\n";
}

}  // namespace

int runEdit(const EditOptions& options) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland)) return noWindow("no display (DISPLAY is not set)");

    glfwSetErrorCallback([](int, const char* text) { g_glfwError = text; });
    if (!glfwInit()) return noWindow(g_glfwError.empty() ? "GLFW could not start" : g_glfwError);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(options.width, options.height, "ShadowLab", nullptr, nullptr);
    if (!window) {
        const std::string why = g_glfwError.empty() ? "no OpenGL 4.5 core context" : g_glfwError;
        glfwTerminate();
        return noWindow(why);
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress))) {
        glfwDestroyWindow(window);
        glfwTerminate();
        return noWindow("the OpenGL functions could not be loaded");
    }

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    // The layout is remembered per user, not per working folder.
    std::string iniPath;
    io.IniFilename = nullptr;  // loaded and saved here, through the atomic writer
    if (std::string error = ensureFolder(userConfigDir()); error.empty()) {
        iniPath = (userConfigDir() / "imgui.ini").string();
        std::string layout;
        if (readRegularFile(iniPath, 1u << 20, layout).empty())
            ImGui::LoadIniSettingsFromMemory(layout.data(), layout.size());
    } else {
        std::cerr << "shadowlab: warning: " << error << "; the panel layout will not be remembered\n";
    }
    editor::applyEditorStyle();
    ImGui_ImplGlfw_InitForOpenGL(window, /*install_callbacks=*/false);
    ImGui_ImplOpenGL3_Init("#version 450 core");

    int status = 0;
    {
        Host host;
        std::unique_ptr<editor::Editor> editorPtr;
        try {
            editor::EditorOptions editorOptions;
            editorOptions.scene = options.scene;
            editorOptions.preset = options.preset;
            editorOptions.screenshotDir =
                options.screenshotDir.empty() ? userScreenshotsDir().string() : options.screenshotDir;
            editorOptions.wake = [&host] {  // on a worker's thread
                host.woken = true;
                glfwPostEmptyEvent();  // thread-safe: ends glfwWaitEvents
            };
            editorPtr = std::make_unique<editor::Editor>(editorOptions);
        } catch (const std::exception& e) {
            std::cerr << "shadowlab edit: " << e.what() << "\n";
            status = 1;
        }
        if (editorPtr) {
            editor::Editor& ed = *editorPtr;
            host.editor = &ed;
            glfwSetWindowUserPointer(window, &host);
            installCallbacks(window);
            glfwFocusWindow(window);
            std::cout << "shadowlab: editor open (" << options.scene << "); Ctrl+Q quits" << std::endl;

            std::string title, controlsWritten;
            while (!ed.quitConfirmed()) {
                // Idle, the window sleeps until input or a worker's wake (editorOptions.wake); while a worker runs
                // it wakes at a modest rate for the progress (redrawing flat out on llvmpipe starves the worker),
                // and for Auto's delay exactly when it falls due.
                const std::optional<double> wait = !host.keys.empty() || host.framesAfterInput > 0
                                                       ? std::optional<double>(0.0)
                                                       : ed.secondsUntilNextFrame();
                if (!wait)
                    glfwWaitEvents();
                else if (*wait <= 0.0)
                    glfwPollEvents();
                else
                    glfwWaitEventsTimeout(*wait);
                // What a worker brought (a result, a scene) settles like input: ImGui lays new content out over a
                // few frames.
                if (host.woken.exchange(false)) host.framesAfterInput = 3;
                if (glfwWindowShouldClose(window)) {
                    glfwSetWindowShouldClose(window, GLFW_FALSE);
                    ed.requestQuit();
                }
                host.keyEvents += host.keys.deliver(window);

                ed.renderFrame();
                ImGui_ImplOpenGL3_NewFrame();
                ImGui_ImplGlfw_NewFrame();
                ImGui::NewFrame();
                ed.buildUi();
                ImGui::Render();

                int fbWidth = 0, fbHeight = 0;
                glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
                glBindFramebuffer(GL_FRAMEBUFFER, 0);
                glViewport(0, 0, fbWidth, fbHeight);
                glClearColor(0.09f, 0.09f, 0.10f, 1.0f);
                glClear(GL_COLOR_BUFFER_BIT);
                ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
                if (std::optional<std::string> path = ed.takeWindowScreenshotRequest()) {
                    glReadBuffer(GL_BACK);
                    const std::string error = editor::writeFramebufferPng(*path, fbWidth, fbHeight);
                    ed.windowScreenshotDone(error.empty() ? *path : error, error.empty());
                }
                glfwSwapBuffers(window);

                if (std::string now = ed.windowTitle(); now != title) {
                    glfwSetWindowTitle(window, now.c_str());
                    title = now;
                }
                writeControlsFile(ed, host, controlsWritten);
                if (io.WantSaveIniSettings) saveLayout(iniPath);
                if (host.framesAfterInput > 0) --host.framesAfterInput;
            }
        }
        editorPtr.reset();  // GL objects go while the context lives
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    saveLayout(iniPath);
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}

}  // namespace shadowlab::editor_window
