#include "editor/timeline.h"

#include "scene/scene_animation.h"
#include "settings/settings_fields.h"

#include <cmath>

namespace shadowlab::editor {

AnimationSpan chosenSpan(const EditorState& state) {
    if (!state.timeline.rest) return {};
    std::string error;
    const std::optional<std::vector<int>> chosen = chosenAnimations(*state.timeline.rest, state.settings.animation.play, error);
    return chosen ? animationSpan(*state.timeline.rest, *chosen) : AnimationSpan{};
}

void advanceTimeline(EditorState& state, double dtSeconds) {
    TimelineState& t = state.timeline;
    if (!t.playing) return;
    const AnimationSpan span = chosenSpan(state);
    if (!(span.end > span.start)) {  // nothing that moves over time
        t.playing = false;
        return;
    }
    double time = double(state.settings.animation.time) + dtSeconds * double(t.speed);
    if (time >= span.end) {
        if (t.loop) {
            time = span.start + std::fmod(time - span.start, span.end - span.start);
        } else {
            time = span.end;
            t.playing = false;
        }
    }
    // Through the key table (its range), but not as a user's edit: playing is no action to answer.
    findSettingsField("animation.time")->set(state.settings, time);
}

bool poseShownScene(EditorState& state) {
    TimelineState& t = state.timeline;
    if (!t.rest || t.rest->animations.empty()) return false;
    if (t.posedAs == state.settings.animation) return false;
    t.posedAs = state.settings.animation;
    auto posed = std::make_shared<Scene>(*t.rest);
    if (std::string error = poseScene(*posed, state.settings.animation); !error.empty()) {
        if (error != t.error) state.say(error, true);
        t.error = error;
        state.scene = t.rest;
        return true;
    }
    t.error.clear();
    state.scene = std::move(posed);
    return true;
}

}  // namespace shadowlab::editor
