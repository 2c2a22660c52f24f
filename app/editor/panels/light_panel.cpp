// Light: the selected light's type, direction as azimuth + elevation, spot / point position, cone and range, its size
// (the soft reference's), colour and intensity; the animation preview.
#include "editor/field_widgets.h"
#include "editor/light_angles.h"
#include "editor/panels/panel_registry.h"

#include <glm/geometric.hpp>

namespace shadowlab::editor {

namespace {

// A vec3 key edited with one ImGui widget (drag or colour picker), recorded and explained like the bound controls.
void vec3Control(EditorState& state, const std::string& key, bool changed, const glm::vec3& value) {
    if (changed) state.edit(key, nlohmann::json::array({value.x, value.y, value.z}));
    state.controls.recordLastItem(controlName(key.c_str()));
    fieldHelp(state, key.c_str());
    showFieldError(state, key.c_str());
}

}  // namespace

void drawLightPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    if (!lightHeader(state)) return;
    ImGui::PushItemWidth(-110.0f);
    auto key = [&](const char* within) { return state.lightKey(within); };
    const LightSettings light = *state.selected();  // a copy: edits below may reallocate the list

    comboField(state, key("type").c_str(), "type");

    if (light.type != LightType::Point) {
        // The key stores a direction vector; people think in azimuth and elevation of where the light comes from.
        LightAngles angles = anglesFromDirection(light.direction);
        bool anglesChanged = ImGui::SliderFloat("azimuth", &angles.azimuthDeg, -180.0f, 180.0f, "%.1f deg");
        state.controls.recordLastItem("light.azimuth");
        anglesChanged |= ImGui::SliderFloat("elevation", &angles.elevationDeg, -89.0f, 89.0f, "%.1f deg");
        state.controls.recordLastItem("light.elevation");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Angle of the light above the horizon (90 = straight down)");
        if (anglesChanged) {
            const glm::vec3 d = directionFromAngles(angles);
            state.edit(key("direction"), nlohmann::json::array({d.x, d.y, d.z}));
        }
        showFieldError(state, key("direction").c_str());
    }

    if (light.type != LightType::Directional) {
        glm::vec3 position = light.position;
        const bool moved = ImGui::DragFloat3("position", &position.x, 0.05f, 0.0f, 0.0f, "%.2f");
        vec3Control(state, key("position"), moved, position);
        if (light.type == LightType::Spot)
            sliderFloatField(state, key("spotConeDeg").c_str(), "cone", 1.0f, 170.0f, "%.1f deg");
        // The label stays short (the sidebar is narrow); the value says what 0 means.
        dragFloatField(state, key("range").c_str(), "range", 0.05f, light.range == 0.0f ? "0 (no limit)" : "%.2f");
    }
    // The soft reference's light size: an angle for a directional light, a disc's radius for spot and point lights.
    const char* sizeFormat = light.size == 0.0f                      ? "0 (hard)"
                             : light.type == LightType::Directional ? "%.2f deg diameter"
                                                                    : "%.3f radius";
    dragFloatField(state, key("size").c_str(), "size", light.type == LightType::Directional ? 0.01f : 0.005f,
                   sizeFormat);
    glm::vec3 color = light.color;
    const bool recoloured = ImGui::ColorEdit3("colour", &color.x, ImGuiColorEditFlags_Float);
    vec3Control(state, key("color"), recoloured, color);
    sliderFloatField(state, key("intensity").c_str(), "intensity", 0.0f, 4.0f, "%.2f");

    ImGui::Separator();
    ImGui::Checkbox("animate", &state.animateLight);
    state.controls.recordLastItem("light.animate");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Rotate the selected light around the scene (a preview: the preset is not changed)");
    if (state.animateLight) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-1.0f);
        ImGui::SliderFloat("##speed", &state.animateDegreesPerSecond, -180.0f, 180.0f, "%.0f deg/s");
    }
    ImGui::PopItemWidth();
}

}  // namespace shadowlab::editor
