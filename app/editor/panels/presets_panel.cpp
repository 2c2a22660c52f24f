// Presets: the shipped presets (read-only) and the user's, load / save / save as / revert, the unsaved marker.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"

#include <imgui_stdlib.h>

namespace shadowlab::editor {

void drawPresetsPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    const bool dirty = state.preset.dirty(state.settings);
    ImGui::Text("%s%s", state.preset.name().c_str(), dirty ? " *" : "");
    state.controls.recordLastItem("preset.current");
    if (dirty || state.preset.shipped()) {
        ImGui::SameLine();
        ImGui::TextDisabled(dirty ? "(unsaved changes)" : "(shipped, read-only)");
    }

    // The list takes the height left above two rows of buttons and the folder line (wrapped: a long path).
    const std::string folder = "yours: " + state.userPresetsDir;
    const float folderHeight = ImGui::CalcTextSize(folder.c_str(), nullptr, false, ImGui::GetContentRegionAvail().x).y;
    const float buttonsHeight = ImGui::GetFrameHeightWithSpacing() * 2.0f + folderHeight + ImGui::GetStyle().ItemSpacing.y;
    if (ImGui::BeginListBox("##presets", ImVec2(-1, std::max(60.0f, ImGui::GetContentRegionAvail().y - buttonsHeight)))) {
        for (const PresetEntry& entry : state.presetList) {
            const bool current = entry.path.string() == state.preset.path();
            std::string label = entry.name + (entry.readOnly ? "" : "   (yours)");
            if (ImGui::Selectable(label.c_str(), current) && !current)
                ctx.actions.requestPreset(entry.path.string(), entry.readOnly);
            state.controls.recordLastItem((entry.readOnly ? "preset.shipped=" : "preset.user=") + entry.name);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", entry.path.string().c_str());
        }
        ImGui::EndListBox();
    }

    if (ImGui::Button("Save (Ctrl+S)")) ctx.actions.savePreset();
    state.controls.recordLastItem("preset.save");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(state.preset.canSaveInPlace() ? "Write %s" : "Shipped presets are read-only: asks for a name",
                          state.preset.path().c_str());
    ImGui::SameLine();
    if (ImGui::Button("Save As...")) ctx.actions.openSaveAs();
    state.controls.recordLastItem("preset.saveAs");
    ImGui::SameLine();
    ImGui::BeginDisabled(!dirty);
    if (ImGui::Button("Revert")) ctx.actions.revertPreset();
    ImGui::EndDisabled();
    state.controls.recordLastItem("preset.revert");

    // Your own presets can be renamed and deleted (moved to deleted/, recoverable); shipped ones are read-only.
    static std::string newName;
    ImGui::BeginDisabled(!state.preset.canSaveInPlace());
    if (ImGui::Button("Rename...")) {
        newName = state.preset.name();
        ImGui::OpenPopup("Rename preset");
    }
    state.controls.recordLastItem("preset.rename");
    ImGui::SameLine();
    if (ImGui::Button("Delete...")) ImGui::OpenPopup("Delete preset");
    state.controls.recordLastItem("preset.delete");
    ImGui::EndDisabled();
    if (ImGui::BeginPopupModal("Rename preset", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
        ImGui::SetNextItemWidth(260.0f);
        bool submit = ImGui::InputText("new name", &newName, ImGuiInputTextFlags_EnterReturnsTrue);
        state.controls.recordLastItem("rename.name");
        submit |= ImGui::Button("Rename", ImVec2(110, 0));
        state.controls.recordLastItem("rename.ok");
        ImGui::SameLine();
        const bool cancel = ImGui::Button("Cancel", ImVec2(110, 0));
        state.controls.recordLastItem("rename.cancel");
        if (submit) ctx.actions.renamePreset(newName);
        if (submit || cancel) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    if (ImGui::BeginPopupModal("Delete preset", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("Move \"%s\" into deleted/ in your presets folder?", state.preset.name().c_str());
        ImGui::TextDisabled("(recoverable: nothing is erased; the current settings stay)");
        const bool confirm = ImGui::Button("Delete", ImVec2(110, 0));
        state.controls.recordLastItem("delete.ok");
        ImGui::SameLine();
        const bool cancel = ImGui::Button("Cancel", ImVec2(110, 0));
        state.controls.recordLastItem("delete.cancel");
        if (confirm) ctx.actions.deletePreset();
        if (confirm || cancel) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    noteText(folder);
}

}  // namespace shadowlab::editor
