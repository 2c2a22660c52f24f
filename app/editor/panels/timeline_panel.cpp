// Timeline: which of the file's animations play (animation.play) and the time the scene is posed at
// (animation.time, a scrub slider over their span); play, pause, loop and speed move the time (editor/timeline.h).
// Skins and morph targets are not played: the loader's warnings say so.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "editor/timeline.h"

#include <cstdio>
#include <string>
#include <vector>

namespace shadowlab::editor {

namespace {

// "all", "none" and each animation by name: choosing one sets animation.play.
void animationCombo(EditorState& state, const Scene& scene) {
    std::vector<std::pair<std::string, std::string>> entries = {{"all", "all"}, {"none", "none (the file's pose)"}};
    for (const Animation& a : scene.animations)
        entries.emplace_back(a.name, std::to_string(a.index) + ": " + a.name);
    const std::string& play = state.settings.animation.play;
    std::string shown = play;
    for (const auto& [value, label] : entries)
        if (value == play) shown = label;
    ImGui::SetNextItemWidth(-80.0f);
    if (ImGui::BeginCombo("animation", shown.c_str())) {
        for (const auto& [value, label] : entries) {
            if (ImGui::Selectable(label.c_str(), value == play) && value != play) state.edit("animation.play", value);
            state.controls.recordLastItem("animation.play=" + value);
        }
        ImGui::EndCombo();
    }
    state.controls.recordLastItem("animation.play");
    fieldHelp(state, "animation.play");
}

}  // namespace

void drawTimelinePanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    TimelineState& t = state.timeline;
    if (!t.rest || t.rest->animations.empty()) {
        ImGui::TextDisabled("this scene has no animations");
        return;
    }
    animationCombo(state, *t.rest);
    if (!t.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", t.error.c_str());
    const AnimationSpan span = chosenSpan(state);

    if (ImGui::Button(t.playing ? "Pause" : "Play", ImVec2(60.0f, 0.0f))) {
        state.userActed();
        t.playing = !t.playing && span.end > span.start;
        // Played from the start again once it ran to the end without looping.
        if (t.playing && !t.loop && double(state.settings.animation.time) >= span.end)
            state.edit("animation.time", span.start);
    }
    state.controls.recordLastItem("timeline.play");
    ImGui::SameLine();
    ImGui::Checkbox("loop", &t.loop);
    state.controls.recordLastItem("timeline.loop");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-80.0f);
    ImGui::SliderFloat("speed", &t.speed, 0.1f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic);
    state.controls.recordLastItem("timeline.speed");

    // Scrubbing pauses the player: the slider holds the time the user points at (the default width: the bound
    // controls record their frame at it).
    if (sliderFloatField(state, "animation.time", "time", float(span.start), float(std::max(span.end, span.start + 1e-3)),
                         "%.3f s"))
        t.playing = false;
    char keys[96];
    std::snprintf(keys, sizeof keys, "keys %.3g to %.3g s; skins and morph targets are not played", span.start,
                  span.end);
    noteText(keys);
}

}  // namespace shadowlab::editor
