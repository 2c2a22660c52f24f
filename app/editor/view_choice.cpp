#include "editor/view_choice.h"

#include "editor/editor_state.h"

#include <imgui.h>

namespace shadowlab::editor {

std::vector<std::string> viewNamesOf(const EditorState& state, std::size_t light) {
    std::vector<std::string> names;
    if (!state.haveStats) return names;
    for (const ShadowViewStats& v : state.stats.views)
        if (v.hasView && v.light == light)
            if (std::string name = viewSuffix(v.kind, v.index); !name.empty()) names.push_back(std::move(name));
    return names;
}

bool followLight(ViewChoice& choice, std::size_t light, const std::vector<std::string>& views) {
    if (choice.light == light && choice.among == views) return false;
    const bool wasChosen = !choice.view.empty();
    choice.view.clear();
    choice.light = light;
    choice.among = views;
    return wasChosen;
}

std::string viewChoiceLabel(const ViewChoice& choice, std::size_t light) {
    if (!choice.view.empty()) return viewName(light, ShadowViewKind::Single, 0) + " " + choice.view;
    const std::size_t n = choice.light == light ? choice.among.size() : 0;
    if (n < 2) return viewName(light, ShadowViewKind::Single, 0);
    const bool cascades = choice.among.front().rfind("cascade:", 0) == 0;
    return viewName(light, ShadowViewKind::Single, 0) + ", all views (" + std::to_string(n) +
           (cascades ? " cascades)" : " cube faces)");
}

bool drawViewChoice(EditorState& state, ViewChoice& choice, std::size_t light, const std::string& id) {
    followLight(choice, light, viewNamesOf(state, light));
    // A light with one view has nothing to choose: no control (the panel's lines stay whole at 1600x900).
    if (choice.among.empty()) return false;
    bool changed = false;
    ImGui::SetNextItemWidth(-FLT_MIN);
    if (ImGui::BeginCombo(("##" + id).c_str(), viewChoiceLabel(choice, light).c_str())) {
        if (ImGui::Selectable("all views", choice.view.empty()) && !choice.view.empty()) {
            choice.view.clear();
            changed = true;
        }
        state.controls.recordLastItem(id + "=all views");
        for (const std::string& name : choice.among) {
            if (ImGui::Selectable(name.c_str(), choice.view == name) && choice.view != name) {
                choice.view = name;
                changed = true;
            }
            state.controls.recordLastItem(id + "=" + name);
        }
        ImGui::EndCombo();
    }
    state.controls.recordLastItem(id);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Which of the light's shadow views the numbers describe (as the CLI's --view): a cube face "
                          "or a cascade, or all of them");
    return changed;
}

}  // namespace shadowlab::editor
