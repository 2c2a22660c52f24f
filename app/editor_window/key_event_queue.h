#pragma once
// ImGui 1.86 reads the keyboard once per frame (io.KeysDown), so a key pressed and released between two frames -
// which is how xdotool and fast typists send them - is lost, and Ctrl can be released before S is seen. GLFW's key
// and character events are queued here and handed to ImGui at most one key event per frame, in order (the input
// queue ImGui 1.87 added does the same). While a text field has the keyboard, printable keys (which then only bring
// their characters) are handed over without waiting for a frame each.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <deque>

namespace shadowlab::editor_window {

class KeyEventQueue {
public:
    void pushKey(int key, int scancode, int action, int mods) { events_.push_back({false, key, scancode, action, mods, 0}); }
    void pushChar(unsigned int c) { events_.push_back({true, 0, 0, 0, 0, c}); }
    bool empty() const { return events_.empty(); }
    // Hands ImGui the characters up to and including the next key event; returns how many key events it handed.
    int deliver(GLFWwindow* window);

private:
    struct Event {
        bool isChar;
        int key, scancode, action, mods;
        unsigned int character;
    };
    std::deque<Event> events_;
};

}  // namespace shadowlab::editor_window
