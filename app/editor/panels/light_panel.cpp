// Light: type, direction as azimuth + elevation, spot position / cone / range, intensity, animation.
#include "editor/field_widgets.h"
#include "editor/light_angles.h"
#include "editor/panels/panel_registry.h"

#include <glm/geometric.hpp>

namespace shadowlab::editor {

void drawLightPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    const LightSettings& light = state.settings.lights[0];
    ImGui::PushItemWidth(-110.0f);

    comboField(state, "light.type", "type");
    checkboxField(state, "light.useSceneLight", "use the scene's light");
    if (state.haveStats) ImGui::TextDisabled("using %s", state.stats.lightSource.c_str());

    // The key stores a direction vector; people think in azimuth and elevation of where the light comes from.
    LightAngles angles = anglesFromDirection(light.direction);
    bool anglesChanged = ImGui::SliderFloat("azimuth", &angles.azimuthDeg, -180.0f, 180.0f, "%.1f deg");
    state.controls.recordLastItem("light.azimuth");
    anglesChanged |= ImGui::SliderFloat("elevation", &angles.elevationDeg, -89.0f, 89.0f, "%.1f deg");
    state.controls.recordLastItem("light.elevation");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Angle of the light above the horizon (90 = straight down)");
    if (anglesChanged) {
        const glm::vec3 d = directionFromAngles(angles);
        state.edit("light.direction", nlohmann::json::array({d.x, d.y, d.z}));
    }
    showFieldError(state, "light.direction");

    if (light.type == LightType::Spot) {
        glm::vec3 position = light.position;
        if (ImGui::DragFloat3("position", &position.x, 0.05f, 0.0f, 0.0f, "%.2f"))
            state.edit("light.position", nlohmann::json::array({position.x, position.y, position.z}));
        state.controls.recordLastItem("light.position");
        fieldHelp(state, "light.position");
        showFieldError(state, "light.position");
        sliderFloatField(state, "light.spotConeDeg", "cone", 1.0f, 170.0f, "%.1f deg");
        // A spot's range is its shadow volume's far plane.
        if (state.settings.lights[0].projection.autoFit) {
            ImGui::TextDisabled("range: fitted to the scene (Projection > auto-fit)");
        } else {
            dragFloatField(state, "projection.far", "range", 0.05f, "%.2f");
        }
    }
    sliderFloatField(state, "light.intensity", "intensity", 0.0f, 4.0f, "%.2f");
    sliderFloatField(state, "light.ambient", "ambient", 0.0f, 1.0f, "%.2f");

    ImGui::Separator();
    ImGui::Checkbox("animate", &state.animateLight);
    state.controls.recordLastItem("light.animate");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Rotate the light around the scene (a preview: the preset is not changed)");
    if (state.animateLight) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-1.0f);
        ImGui::SliderFloat("##speed", &state.animateDegreesPerSecond, -180.0f, 180.0f, "%.0f deg/s");
    }
    ImGui::PopItemWidth();
}

}  // namespace shadowlab::editor
