#include "editor/editor_state.h"

#include <iostream>

namespace shadowlab::editor {

void FrameHistory::push(float frame, float shadow) {
    frameMs.push_back(frame);
    shadowPassMs.push_back(shadow);
    while (frameMs.size() > kLength) frameMs.pop_front();
    while (shadowPassMs.size() > kLength) shadowPassMs.pop_front();
}

bool EditorState::edit(std::string_view key, const nlohmann::json& value) {
    const std::string error = applyEdit(settings, key, value, limits);
    if (error.empty()) {
        fieldErrors.erase(std::string(key));
        return true;
    }
    fieldErrors[std::string(key)] = error;
    say(error, true);
    return false;
}

void EditorState::say(std::string text, bool error) {
    // Printed too, so scripts and users in a terminal see what the window says.
    (error ? std::cerr : std::cout) << (error ? "shadowlab: error: " : "shadowlab: ") << text << std::endl;
    messages.push_back(Message{std::move(text), error, time});
    if (messages.size() > 50) messages.erase(messages.begin());
}

const std::string* EditorState::fieldError(const std::string& key) const {
    auto it = fieldErrors.find(key);
    return it == fieldErrors.end() ? nullptr : &it->second;
}

}  // namespace shadowlab::editor
