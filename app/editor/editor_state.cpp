#include "editor/editor_state.h"

#include "editor/message_log.h"
#include "light/depth_format_change.h"
#include "settings/settings_fields.h"

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
        userActed();
        fieldErrors.erase(std::string(key));
        // The key within its light and the light it names: aliases ("shadow.depthBias") and "lights.N." alike.
        const SettingsField* field = findSettingsField(key);
        const std::string_view within = field ? field->lightKey() : std::string_view{};
        const std::size_t light = field && field->light >= 0 ? std::size_t(field->light) : 0;
        if (within == "shadow.depthBias" || within == "shadow.depthFormat") undo.reset();  // its numbers are gone
        if (within == "shadow.depthFormat" && light < before.lights.size() &&
            settings.lights[light].shadow.format != before.lights[light].shadow.format) {
            // The receivers' depth decides D32F's step; the newest frame knows it.
            const std::optional<double> receiverDepth =
                haveStats && stats.bias.valid ? std::optional(stats.bias.receiverDepthMedian) : std::nullopt;
            const DepthFormatChange change =
                changeDepthFormat(before.lights[light].shadow, settings.lights[light].shadow.format, receiverDepth);
            if (!change.note.empty()) {
                settings.lights[light].shadow = change.shadow;
                undo = UndoStep{before, change.note, light};
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
    const std::size_t light = undo->light;
    if (light < settings.lights.size() && light < undo->before.lights.size()) {
        // Only what the step changed: edits made since (slope, filter, ...) stay.
        settings.lights[light].shadow.format = undo->before.lights[light].shadow.format;
        settings.lights[light].shadow.depthBias = undo->before.lights[light].shadow.depthBias;
    }
    const std::string note = undo->note;
    undo.reset();
    say("Undone: " + note);
}

std::string EditorState::lightKey(std::string_view key) const {
    return "lights." + std::to_string(selectedLight) + "." + std::string(key);
}

const LightSettings* EditorState::selected() const {
    return selectedLight < settings.lights.size() ? &settings.lights[selectedLight] : nullptr;
}

void EditorState::clampSelectedLight() {
    if (selectedLight >= settings.lights.size()) selectedLight = settings.lights.empty() ? 0 : settings.lights.size() - 1;
}

const ShadowViewStats* EditorState::shownView() const {
    if (!haveStats) return nullptr;
    const ShadowViewStats* firstOfSelected = nullptr;
    const ShadowViewStats* first = nullptr;
    for (const ShadowViewStats& v : stats.views) {
        if (!v.hasView) continue;
        if (v.light == viewer.light && v.kind == viewer.kind && v.index == viewer.index) return &v;
        if (!firstOfSelected && v.light == selectedLight) firstOfSelected = &v;
        if (!first) first = &v;
    }
    return firstOfSelected ? firstOfSelected : first;
}

std::vector<const ShadowViewStats*> EditorState::selectedLightViews() const {
    std::vector<const ShadowViewStats*> views;
    if (!haveStats) return views;
    for (const ShadowViewStats& v : stats.views)
        if (v.hasView && v.light == selectedLight) views.push_back(&v);
    return views;
}

void EditorState::log(Message message) {
    // Printed too, so scripts and users in a terminal see what the window says.
    (message.error ? std::cerr : std::cout) << (message.error ? "shadowlab: error: " : "shadowlab: ") << message.text
                                            << std::endl;
    message.serial = nextSerial_++;
    // An action's result or any error takes the status line and stands; automatic news only when nothing stands.
    if (!message.automatic || message.error || !statusStands_) {
        statusSerial_ = message.serial;
        statusStands_ = !message.automatic || message.error;
    }
    messages.push_back(std::move(message));
    if (messages.size() > kMessagesKept) messages.erase(messages.begin());
}

void EditorState::say(std::string text, bool error) { log(Message{std::move(text), error, time, clockStamp()}); }

void EditorState::sayAutomatic(std::string text, bool error) {
    log(Message{std::move(text), error, time, clockStamp(), /*automatic=*/true});
}

const Message* EditorState::statusMessage() const {
    for (auto m = messages.rbegin(); m != messages.rend(); ++m)
        if (m->serial <= statusSerial_) return &*m;  // the shown one, or (dropped from the log) the newest before it
    return lastMessage();
}

const std::string* EditorState::fieldError(const std::string& key) const {
    auto it = fieldErrors.find(key);
    return it == fieldErrors.end() ? nullptr : &it->second;
}

}  // namespace shadowlab::editor
