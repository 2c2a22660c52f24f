#include "editor_window/key_event_queue.h"

#include <backends/imgui_impl_glfw.h>

namespace shadowlab::editor_window {

void KeyEventQueue::deliver(GLFWwindow* window) {
    while (!events_.empty()) {
        const Event e = events_.front();
        events_.pop_front();
        if (e.isChar) {
            ImGui_ImplGlfw_CharCallback(window, e.character);
            continue;
        }
        if (e.action == GLFW_REPEAT) continue;  // ImGui repeats held keys itself
        ImGui_ImplGlfw_KeyCallback(window, e.key, e.scancode, e.action, e.mods);
        return;
    }
}

}  // namespace shadowlab::editor_window
