// Projection: the selected light's volume — auto-fit, or a manual ortho size, near and far; depth clamp; for a
// directional light the fit (scene or cascades) and the cascades' keys.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"

namespace shadowlab::editor {

namespace {

// The cascades' keys, and what the frame made of them: each cascade's depth range and texel size.
void drawCascadeControls(EditorState& state) {
    auto key = [&](const char* within) { return state.lightKey(within); };
    comboField(state, key("projection.cascadeCount").c_str(), "cascades");
    comboField(state, key("projection.cascadeFit").c_str(), "cascade fit");
    comboField(state, key("projection.depthBounds").c_str(), "depth bounds");
    sliderFloatField(state, key("projection.splitLambda").c_str(), "split lambda", 0.0f, 1.0f, "%.2f");
    dragFloatField(state, key("projection.shadowDistance").c_str(), "shadow distance", 0.5f, "%.1f");
    sliderFloatField(state, key("projection.blendBand").c_str(), "blend band", 0.0f, 0.5f, "%.2f");
    checkboxField(state, key("projection.depthClamp").c_str(), "depth clamp (casters before near still cast)");
    for (const ShadowViewStats* v : state.selectedLightViews())
        if (v->kind == ShadowViewKind::Cascade)
            ImGui::TextDisabled("cascade %d: depth %.3g..%.3g, texel %.3g", v->index, v->slice.nearDepth,
                                v->slice.farDepth, v->space.texelWorldSize);
}

}  // namespace

void drawProjectionPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    if (!lightHeader(state)) return;
    auto key = [&](const char* within) { return state.lightKey(within); };
    const std::size_t index = state.selectedLight;
    ImGui::PushItemWidth(-120.0f);
    if (state.selected()->type == LightType::Directional) {
        comboField(state, key("projection.fit").c_str(), "fit");
        if (state.selected()->projection.fit == ProjectionFit::Cascades) {
            drawCascadeControls(state);
            ImGui::PopItemWidth();
            return;
        }
    }
    // The views auto-fit chose (a point light's faces share near and far), read before a change to auto-fit.
    const std::vector<const ShadowViewStats*> views = state.selectedLightViews();
    auto useFitted = [&] {
        if (std::string error = manualFromFitted(state.settings, index, views.front()->space); !error.empty())
            state.say("the fitted values cannot be edited: " + error, true);
    };
    const bool wasAutoFit = state.selected()->projection.autoFit;
    // Unticked: manual tuning starts from what auto-fit chose, not from the preset's old manual values.
    if (checkboxField(state, key("projection.autoFit").c_str(), "auto-fit to the scene") && wasAutoFit &&
        !views.empty() && !state.selected()->projection.autoFit)
        useFitted();
    const bool autoFit = state.selected()->projection.autoFit;
    ImGui::BeginDisabled(autoFit);
    if (state.selected()->type == LightType::Directional)
        dragFloatField(state, key("projection.orthoSize").c_str(), "ortho size", 0.05f, "%.2f");
    dragFloatField(state, key("projection.near").c_str(), "near", 0.01f, "%.3f");
    dragFloatField(state, key("projection.far").c_str(), "far", 0.05f, "%.2f");
    ImGui::EndDisabled();
    if (!views.empty()) {
        const LightSpace& light = views.front()->space;
        if (light.perspective)
            ImGui::TextDisabled("in use: near %.3g, far %.3g", light.nearPlane, light.farPlane);
        else
            ImGui::TextDisabled("in use: size %.3g, near %.3g, far %.3g", light.orthoSize, light.nearPlane,
                                light.farPlane);
        if (autoFit && ImGui::SmallButton("edit these values")) useFitted();
        state.controls.recordLastItem("projection.useFitted");
    }
    checkboxField(state, key("projection.depthClamp").c_str(), "depth clamp (casters before near still cast)");
    ImGui::PopItemWidth();
}

}  // namespace shadowlab::editor
