#include "editor/editor_state.h"

#include "editor/message_log.h"
#include "light/depth_format_change.h"

#include <iostream>

namespace shadowlab::editor {

void FrameHistory::push(float frame, float shadow) {
    frameMs.push_back(frame);
    shadowPassMs.push_back(shadow);
    while (frameMs.size() > kLength) frameMs.pop_front();
    while (shadowPassMs.size() > kLength) shadowPassMs.pop_front();
}

bool EditorState::edit(std::string_view key, const nlohmann::json& value) {
    const Settings before = settings;
    const std::string error = applyEdit(settings, key, value, limits);
    if (error.empty()) {
        fieldErrors.erase(std::string(key));
        if (key == "shadow.depthBias" || key == "shadow.depthFormat") undo.reset();  // its numbers are gone
        if (key == "shadow.depthFormat" && settings.lights[0].shadow.format != before.lights[0].shadow.format) {
            // The receivers' depth decides D32F's step; the newest frame knows it.
            const std::optional<double> receiverDepth =
                haveStats && stats.bias.valid ? std::optional(stats.bias.receiverDepthMedian) : std::nullopt;
            const DepthFormatChange change = changeDepthFormat(before.lights[0].shadow, settings.lights[0].shadow.format, receiverDepth);
            if (!change.note.empty()) {
                settings.lights[0].shadow = change.shadow;
                undo = UndoStep{before, change.note};
                say(change.note);
            }
        }
        return true;
    }
    fieldErrors[std::string(key)] = error;
    say(error, true);
    return false;
}

void EditorState::undoLastStep() {
    if (!undo) return;
    // Only what the step changed: edits made since (slope, filter, ...) stay.
    settings.lights[0].shadow.format = undo->before.lights[0].shadow.format;
    settings.lights[0].shadow.depthBias = undo->before.lights[0].shadow.depthBias;
    const std::string note = undo->note;
    undo.reset();
    say("Undone: " + note);
}

void EditorState::say(std::string text, bool error) {
    // Printed too, so scripts and users in a terminal see what the window says.
    (error ? std::cerr : std::cout) << (error ? "shadowlab: error: " : "shadowlab: ") << text << std::endl;
    messages.push_back(Message{std::move(text), error, time, clockStamp()});
    if (messages.size() > kMessagesKept) messages.erase(messages.begin());
}

const std::string* EditorState::fieldError(const std::string& key) const {
    auto it = fieldErrors.find(key);
    return it == fieldErrors.end() ? nullptr : &it->second;
}

}  // namespace shadowlab::editor
