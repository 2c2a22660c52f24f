// Lights: the list of lights (type, colour, shadow, enabled), add / remove / duplicate, and which one the Light,
// Shadow map and Projection panels edit; the ambient term and the scene's own lights. Adding sets "lights.<count>.type" (the key table appends a light);
// every change is an edit like any other, so validation, refusals and the preset's "changed" mark behave the same.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"

#include <string>

namespace shadowlab::editor {

namespace {

// A list change that is not one key (remove, duplicate): on refusal the settings stay and the reason is shown.
void listChange(EditorState& state, const std::string& error, const std::string& done) {
    if (!error.empty()) {
        state.say(error, true);
        return;
    }
    state.clampSelectedLight();
    state.say(done);
}

void addButtons(EditorState& state) {
    const std::size_t count = state.settings.lights.size();
    ImGui::TextUnformatted("add");
    for (const char* type : {"directional", "spot", "point"}) {
        ImGui::SameLine();
        ImGui::BeginDisabled(count >= kMaxLights);
        if (ImGui::SmallButton(type) && state.edit("lights." + std::to_string(count) + ".type", type))
            state.selectedLight = count;  // the new light is what the user wants to tune next
        ImGui::EndDisabled();
        state.controls.recordLastItem(std::string("lights.add.") + type);
    }
}

void lightRow(EditorState& state, std::size_t i) {
    const LightSettings light = state.settings.lights[i];  // a copy: the checkboxes below may change the list
    const std::string prefix = "lights." + std::to_string(i) + ".";
    ImGui::PushID(int(i));
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const std::string label = std::to_string(i) + " " + lightTypeText(state.settings, i);
    if (ImGui::Selectable(label.c_str(), state.selectedLight == i, ImGuiSelectableFlags_SpanAllColumns |
                                                                       ImGuiSelectableFlags_AllowItemOverlap))
        state.selectedLight = i;
    state.controls.recordLastItem("lights.select." + std::to_string(i));
    ImGui::TableNextColumn();
    ImGui::ColorButton("##colour", ImVec4(light.color.x, light.color.y, light.color.z, 1.0f),
                       ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_Float, ImVec2(14, 14));
    ImGui::SameLine();
    ImGui::Text("x%.2g", double(light.intensity));
    // Bound to the keys directly (not checkboxField): every row has these two, so each is recorded under its key.
    for (auto [within, text] : {std::pair{"enabled", "on"}, std::pair{"castsShadows", "casts"}}) {
        ImGui::TableNextColumn();
        const std::string key = prefix + within;
        bool value = within == std::string("enabled") ? light.enabled : light.castsShadows;
        if (ImGui::Checkbox(text, &value)) state.edit(key, value);
        state.controls.recordLastItem(key);
        fieldHelp(state, key.c_str());
    }
    ImGui::PopID();
}

// What lights every light's scene: the ambient term, and the scene file's own lights instead of the list.
void globalLighting(EditorState& state) {
    ImGui::PushItemWidth(-110.0f);
    sliderFloatField(state, "ambient", "ambient", 0.0f, 1.0f, "%.2f");
    checkboxField(state, "useSceneLights", "use the scene's lights instead");
    if (state.haveStats) noteText("using " + state.stats.lightSource);  // wrapped: it lists every light
    ImGui::PopItemWidth();
}

}  // namespace

void drawLightsPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    state.clampSelectedLight();
    addButtons(state);
    const std::size_t count = state.settings.lights.size();
    if (count == 0) {
        ImGui::TextDisabled("no lights: the scene is lit by ambient only");
        globalLighting(state);
        return;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("duplicate"))
        listChange(state, duplicateLight(state.settings, state.selectedLight),
                   "light " + std::to_string(state.selectedLight) + " duplicated as light " + std::to_string(count));
    state.controls.recordLastItem("lights.duplicate");
    ImGui::SameLine();
    if (ImGui::SmallButton("remove"))
        listChange(state, removeLight(state.settings, state.selectedLight),
                   "light " + std::to_string(state.selectedLight) + " removed" +
                       (count == 1 ? ": no lights left, ambient only" : ""));
    state.controls.recordLastItem("lights.remove");

    if (ImGui::BeginTable("lights", 4, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("light", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("colour");
        ImGui::TableSetupColumn("enabled");
        ImGui::TableSetupColumn("shadow");
        for (std::size_t i = 0; i < state.settings.lights.size(); ++i) lightRow(state, i);
        ImGui::EndTable();
    }
    globalLighting(state);
}

}  // namespace shadowlab::editor
