// Export: the edited settings as a D3D12 / D3D11 / Vulkan / OpenGL snippet or JSON (what `shadowlab export` writes),
// for the selected light or every light; copied to the clipboard or saved (screenshots folder, or a typed path).
#include "editor/editor.h"
#include "editor/panels/panel_registry.h"
#include "editor/view_choice.h"
#include "export/export_snippets.h"
#include "light/scene_lights.h"
#include "settings/atomic_file.h"

#include <imgui_stdlib.h>

#include <array>
#include <string>

namespace shadowlab::editor {

namespace {

// The panel's own choices (not settings: they never mark the preset as changed).
struct ExportPanelState {
    int format = 0;          // index into kFormats
    int light = -2;          // -2: follow the selected light; -1: every light; else that light
    ViewChoice view;         // with one light: all its views or one (a cube face, a cascade)
    std::string savePath;    // empty: a stamped file in the screenshots folder
};

struct FormatChoice {
    const char* label;
    const char* name;       // --format's word
    const char* extension;
};
constexpr std::array<FormatChoice, 5> kFormats = {{{"Direct3D 12", "d3d12", ".h"},
                                                   {"Direct3D 11", "d3d11", ".h"},
                                                   {"Vulkan", "vulkan", ".h"},
                                                   {"OpenGL", "gl", ".h"},
                                                   {"JSON", "json", ".json"}}};

}  // namespace

void drawExportPanel(PanelContext& ctx) {
    static ExportPanelState ui;
    EditorState& state = ctx.state;
    const std::size_t lights = withEffectiveLights(state.settings, *state.scene).lights.size();

    ImGui::SetNextItemWidth(-FLT_MIN);
    if (ImGui::BeginCombo("##format", kFormats[std::size_t(ui.format)].label)) {
        for (int i = 0; i < int(kFormats.size()); ++i) {
            if (ImGui::Selectable(kFormats[std::size_t(i)].label, i == ui.format)) ui.format = i;
            state.controls.recordLastItem(std::string("export.format=") + kFormats[std::size_t(i)].name);
        }
        ImGui::EndCombo();
    }
    state.controls.recordLastItem("export.format");
    // The light: the selected one unless the user picked another or "all lights".
    const std::size_t selected = state.selectedLight;
    const auto lightText = [&](int choice) -> std::string {
        if (choice == -1) return "all lights";
        const std::size_t i = choice == -2 ? selected : std::size_t(choice);
        return (choice == -2 ? "selected: light " : "light ") + std::to_string(i);
    };
    if (ui.light >= int(lights)) ui.light = -2;
    ImGui::SetNextItemWidth(-FLT_MIN);
    if (ImGui::BeginCombo("##light", lightText(ui.light).c_str())) {
        if (ImGui::Selectable(lightText(-2).c_str(), ui.light == -2)) ui.light = -2;
        state.controls.recordLastItem("export.light=selected");
        if (ImGui::Selectable("all lights", ui.light == -1)) ui.light = -1;
        state.controls.recordLastItem("export.light=all");
        for (int i = 0; i < int(lights); ++i) {
            if (ImGui::Selectable(lightText(i).c_str(), ui.light == i)) ui.light = i;
            state.controls.recordLastItem("export.light=" + std::to_string(i));
        }
        ImGui::EndCombo();
    }
    state.controls.recordLastItem("export.light");

    std::optional<std::size_t> only;
    if (ui.light == -2 && lights > 0) only = std::min(selected, lights - 1);
    if (ui.light >= 0) only = std::size_t(ui.light);
    // The view: one light's cube face or cascade, or all its views (every light: all views of each).
    if (only) {
        drawViewChoice(state, ui.view, *only, "export.view");
    } else {
        ui.view = {};
        ImGui::BeginDisabled();
        ImGui::SetNextItemWidth(-FLT_MIN);
        if (ImGui::BeginCombo("##export.view", "every light, all views")) ImGui::EndCombo();
        ImGui::EndDisabled();
        state.controls.recordLastItem("export.view");
    }
    const FormatChoice& format = kFormats[std::size_t(ui.format)];
    std::string error;
    // A cascaded light's cascades follow the viewport's camera: the one the newest frame fitted them to.
    const ViewCamera* camera = nullptr;
    for (const ShadowViewStats& v : state.stats.views)
        if (v.hasView && v.kind == ShadowViewKind::Cascade) camera = &v.slice.camera;
    const std::optional<ShadowExportSet> set =
        exportForScene(state.settings, *state.scene, state.sceneSpec, only, error, camera, only ? ui.view.view : "");
    std::string text = set ? exportSnippet(*set, *parseExportFormat(format.name)) : "export failed: " + error;

    const float buttons = ImGui::GetFrameHeightWithSpacing() * 2.5f;
    ImGui::InputTextMultiline("##snippet", &text, ImVec2(-FLT_MIN, std::max(ImGui::GetContentRegionAvail().y - buttons, 120.0f)),
                              ImGuiInputTextFlags_ReadOnly);
    state.controls.recordLastItem("export.snippet");
    ImGui::BeginDisabled(!set);
    if (ImGui::Button("Copy to clipboard")) {
        ImGui::SetClipboardText(text.c_str());
        state.say("export: " + std::string(format.name) + " snippet of " +
                  (only ? viewChoiceLabel(ui.view, *only) : std::string("every light")) + " copied (" +
                  std::to_string(text.size()) + " bytes)");
    }
    state.controls.recordLastItem("export.copy");
    ImGui::SameLine();
    if (ImGui::Button("Save")) {
        const std::string path =
            ui.savePath.empty() ? stampedPath(state.screenshotDir, std::string("export-") + format.name, format.extension)
                                : ui.savePath;
        if (std::string failure = writeFileAtomically(path, text); !failure.empty())
            state.say("export not saved: " + failure, true);
        else
            state.say("export: " + path);
    }
    ImGui::EndDisabled();
    ImGui::SetNextItemWidth(-FLT_MIN);
    ImGui::InputTextWithHint("##savePath", "save to (default: the screenshots folder)", &ui.savePath);
}

}  // namespace shadowlab::editor
