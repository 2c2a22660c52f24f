// Projection: the light's volume — auto-fit, or a manual ortho size, near and far; depth clamp.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"

namespace shadowlab::editor {

void drawProjectionPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    ImGui::PushItemWidth(-120.0f);
    checkboxField(state, "projection.autoFit", "auto-fit to the scene");
    const bool autoFit = state.settings.lights[0].projection.autoFit;
    ImGui::BeginDisabled(autoFit);
    if (state.settings.lights[0].type == LightType::Directional)
        dragFloatField(state, "projection.orthoSize", "ortho size", 0.05f, "%.2f");
    dragFloatField(state, "projection.near", "near", 0.01f, "%.3f");
    dragFloatField(state, "projection.far", "far", 0.05f, "%.2f");
    ImGui::EndDisabled();
    if (state.haveStats) {
        const LightSpace& light = state.stats.light;
        if (light.perspective)
            ImGui::TextDisabled("in use: near %.3g, far %.3g", light.nearPlane, light.farPlane);
        else
            ImGui::TextDisabled("in use: size %.3g, near %.3g, far %.3g", light.orthoSize, light.nearPlane,
                                light.farPlane);
        if (autoFit && ImGui::SmallButton("edit these values")) {
            // Start manual tuning from what auto-fit chose, so turning it off does not jump.
            Settings manual = state.settings;
            manual.lights[0].projection.autoFit = false;
            if (!light.perspective) manual.lights[0].projection.orthoSize = float(light.orthoSize);
            manual.lights[0].projection.nearPlane = float(light.nearPlane);
            manual.lights[0].projection.farPlane = float(light.farPlane);
            if (manual.validate().empty())
                state.settings = manual;
            else
                state.say("the fitted values cannot be edited: " + manual.validate().front(), true);
        }
        state.controls.recordLastItem("projection.useFitted");
    }
    checkboxField(state, "projection.depthClamp", "depth clamp (casters before near still cast)");
    ImGui::PopItemWidth();
}

}  // namespace shadowlab::editor
