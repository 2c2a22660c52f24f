#include "editor_window/key_event_queue.h"

#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

namespace shadowlab::editor_window {

int KeyEventQueue::deliver(GLFWwindow* window) {
    int keys = 0;
    while (!events_.empty()) {
        const Event e = events_.front();
        events_.pop_front();
        if (e.isChar) {
            ImGui_ImplGlfw_CharCallback(window, e.character);
            continue;
        }
        if (e.action == GLFW_REPEAT) continue;  // ImGui repeats held keys itself
        ImGui_ImplGlfw_KeyCallback(window, e.key, e.scancode, e.action, e.mods);
        ++keys;
        // While a text field has the keyboard, a printable key without Ctrl / Alt / Super only brings its character
        // (ImGui types from characters; no shortcut reads those keys then): it needs no frame of its own, so a burst
        // of typing costs one frame instead of two per key (each a whole window redraw on a software rasterizer).
        const bool textKey = e.key >= GLFW_KEY_SPACE && e.key <= GLFW_KEY_GRAVE_ACCENT &&
                             !(e.mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER));
        if (!(textKey && ImGui::GetIO().WantTextInput)) return keys;
    }
    return keys;
}

}  // namespace shadowlab::editor_window
