// Scene: built-in scenes, a path field, recent files; loading runs on a thread and shows its progress here.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "scene/builtin_scenes.h"

#include <imgui_stdlib.h>

#include <cmath>

namespace shadowlab::editor {

namespace {

// "Free camera" and the file's cameras by name (by index when unnamed): choosing one moves the view to it and sets
// camera.sceneCamera.
void sceneCameraCombo(PanelContext& ctx) {
    EditorState& state = ctx.state;
    if (!state.scene) return;
    const std::vector<SceneCamera>& cameras = state.scene->cameras;
    const auto label = [&](int index) {
        if (index < 0) return std::string("Free camera");
        const SceneCamera& c = cameras[std::size_t(index)];
        return std::to_string(index) + ": " + c.name + (c.orthographic ? " (orthographic)" : "");
    };
    const int chosen = state.settings.camera.sceneCamera;
    const bool known = chosen >= -1 && chosen < int(cameras.size());
    ImGui::SetNextItemWidth(-80.0f);
    ImGui::BeginDisabled(cameras.empty() && chosen == -1);
    if (ImGui::BeginCombo("camera", known ? label(chosen).c_str() : "(not in this scene)")) {
        for (int i = -1; i < int(cameras.size()); ++i) {
            if (ImGui::Selectable(label(i).c_str(), i == chosen)) ctx.actions.chooseSceneCamera(i);
            state.controls.recordLastItem("scene.camera=" + std::to_string(i));
        }
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    state.controls.recordLastItem("scene.camera");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", cameras.empty() ? "This scene's file has no cameras: the view is the free camera"
                                                : "View from one of the file's cameras (camera.sceneCamera, saved with "
                                                  "the preset; the aspect ratio is the view's). Moving the view "
                                                  "leaves it");
}

}  // namespace

void drawScenePanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    if (state.scene)
        ImGui::Text("%s: %zu triangles", state.scene->name.c_str(), state.scene->triangleCount());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", state.sceneSpec.c_str());

    ImGui::SetNextItemWidth(-80.0f);
    const bool builtinNow = state.sceneSpec.rfind(kBuiltinPrefix, 0) == 0;
    if (ImGui::BeginCombo("built-in", builtinNow ? state.sceneSpec.c_str() + 8 : "(a file)")) {
        for (const std::string& name : builtinSceneNames()) {
            if (ImGui::Selectable(name.c_str(), state.sceneSpec == kBuiltinPrefix + name))
                ctx.actions.requestScene(kBuiltinPrefix + name);
            state.controls.recordLastItem("scene.builtin=" + name);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", builtinSceneDescription(name).c_str());
        }
        ImGui::EndCombo();
    }
    state.controls.recordLastItem("scene.builtin");

    ImGui::SetNextItemWidth(-80.0f);
    bool open = ImGui::InputTextWithHint("##path", ".gltf / .glb path", &state.scenePathInput,
                                         ImGuiInputTextFlags_EnterReturnsTrue);
    state.controls.recordLastItem("scene.path");
    ImGui::SameLine();
    open |= ImGui::Button("Open", ImVec2(-1, 0));
    state.controls.recordLastItem("scene.open");
    if (open) ctx.actions.requestScene(state.scenePathInput);

    const auto& recent = state.recentFiles.items();
    ImGui::SetNextItemWidth(-80.0f);
    ImGui::BeginDisabled(recent.empty());
    if (ImGui::BeginCombo("recent", recent.empty() ? "(none yet)" : "")) {
        for (const std::string& spec : recent)
            if (ImGui::Selectable(spec.c_str())) ctx.actions.requestScene(spec);
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    state.controls.recordLastItem("scene.recent");

    sceneCameraCombo(ctx);

    if (state.loading) {
        const SceneLoadProgress& p = *state.loading;
        char text[96];
        if (p.fileBytes)
            std::snprintf(text, sizeof text, "%s %.1f s (%.1f MB)", p.stage.c_str(), p.elapsedSeconds,
                          double(*p.fileBytes) / 1e6);
        else
            std::snprintf(text, sizeof text, "%s %.1f s", p.stage.c_str(), p.elapsedSeconds);
        // The loader cannot tell how far it is: the bar sweeps to show the window is alive.
        ImGui::ProgressBar(float(std::fmod(p.elapsedSeconds * 0.5, 1.0)), ImVec2(-1, 0), text);
        state.controls.recordLastItem("scene.progress");
    } else {
        ImGui::TextDisabled("or drop a .gltf / .glb onto the window");
    }
}

}  // namespace shadowlab::editor
