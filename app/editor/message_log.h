#pragma once
// The status line's message log: a "Log" button that opens a popup with the last messages (EditorState keeps 50),
// each with its wall-clock time, errors in red, the newest at the bottom.
#include "editor/editor_state.h"

namespace shadowlab::editor {

// The button (call inside the status line) and, while open, the popup above it.
void messageLogButton(EditorState& state);

// "HH:MM:SS" local time now (the stamp a message gets).
std::string clockStamp();
// The local time now in a strftime format (clockStamp: "%H:%M:%S").
std::string localTimeText(const char* format);

}  // namespace shadowlab::editor
