// Projection: the selected light's volume — auto-fit, or a manual ortho size, near and far; depth clamp.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"

namespace shadowlab::editor {

void drawProjectionPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    if (!lightHeader(state)) return;
    auto key = [&](const char* within) { return state.lightKey(within); };
    const std::size_t index = state.selectedLight;
    ImGui::PushItemWidth(-120.0f);
    checkboxField(state, key("projection.autoFit").c_str(), "auto-fit to the scene");
    const bool autoFit = state.selected()->projection.autoFit;
    ImGui::BeginDisabled(autoFit);
    if (state.selected()->type == LightType::Directional)
        dragFloatField(state, key("projection.orthoSize").c_str(), "ortho size", 0.05f, "%.2f");
    dragFloatField(state, key("projection.near").c_str(), "near", 0.01f, "%.3f");
    dragFloatField(state, key("projection.far").c_str(), "far", 0.05f, "%.2f");
    ImGui::EndDisabled();
    if (const std::vector<const ShadowViewStats*> views = state.selectedLightViews(); !views.empty()) {
        const LightSpace& light = views.front()->space;  // a point light's faces share near and far
        if (light.perspective)
            ImGui::TextDisabled("in use: near %.3g, far %.3g", light.nearPlane, light.farPlane);
        else
            ImGui::TextDisabled("in use: size %.3g, near %.3g, far %.3g", light.orthoSize, light.nearPlane,
                                light.farPlane);
        if (autoFit && ImGui::SmallButton("edit these values")) {
            // Start manual tuning from what auto-fit chose, so turning it off does not jump.
            Settings manual = state.settings;
            ProjectionSettings& projection = manual.lights[index].projection;
            projection.autoFit = false;
            if (!light.perspective) projection.orthoSize = float(light.orthoSize);
            projection.nearPlane = float(light.nearPlane);
            projection.farPlane = float(light.farPlane);
            if (manual.validate().empty())
                state.settings = manual;
            else
                state.say("the fitted values cannot be edited: " + manual.validate().front(), true);
        }
        state.controls.recordLastItem("projection.useFitted");
    }
    checkboxField(state, key("projection.depthClamp").c_str(), "depth clamp (casters before near still cast)");
    ImGui::PopItemWidth();
}

}  // namespace shadowlab::editor
