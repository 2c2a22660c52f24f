// Outliner: the scene file's node tree, each node with a "casts shadows" box. Unticking a node adds its path to
// casters.excluded (its whole subtree then casts none, in the shadow maps and in the accuracy reference); ticking it
// removes the path. In a scene with animations (or static / dynamic choices) a second box says whether the node is a
// static caster (kept in a cachedStatic light's cached depth): it shows the rule's answer (no playing animation moves
// it), and a click that contradicts the rule writes the path to casters.static or casters.dynamic; one that agrees
// with it removes the path again. Paths the settings name but the scene lacks are listed (a warning, not an error).
#include "editor/panels/panel_registry.h"
#include "scene/scene_animation.h"
#include "scene/scene_casters.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab::editor {

namespace {

void setExcluded(EditorState& state, const std::string& path, bool excluded) {
    std::vector<std::string> list = state.settings.casters.excluded;
    const auto it = std::find(list.begin(), list.end(), path);
    if (excluded && it == list.end()) list.push_back(path);
    if (!excluded && it != list.end()) list.erase(it);
    state.edit("casters.excluded", list);
}

std::vector<std::string> without(std::vector<std::string> list, const std::string& path) {
    list.erase(std::remove(list.begin(), list.end(), path), list.end());
    return list;
}

// Makes the node static or dynamic with the fewest overrides: none where the rule (animations, ancestors' choices)
// already gives that answer.
void setStatic(EditorState& state, const Scene& scene, const std::vector<int>& playing, int index, bool isStatic) {
    const std::string& path = scene.nodes[std::size_t(index)].path;
    CasterSettings casters = state.settings.casters;
    casters.forcedStatic = without(casters.forcedStatic, path);
    casters.forcedDynamic = without(casters.forcedDynamic, path);
    const bool byRule = staticNodes(scene, playing, casters)[std::size_t(index)] != 0;
    if (isStatic != byRule) (isStatic ? casters.forcedStatic : casters.forcedDynamic).push_back(path);
    if (casters.forcedStatic != state.settings.casters.forcedStatic)
        state.edit("casters.static", casters.forcedStatic);
    if (casters.forcedDynamic != state.settings.casters.forcedDynamic)
        state.edit("casters.dynamic", casters.forcedDynamic);
}

struct NodeBoxes {
    const std::vector<char>& casting;
    const std::vector<char>* statics;  // null: the scene has nothing that moves and no static / dynamic choice
    const std::vector<int>& playing;
};

void drawNode(EditorState& state, const Scene& scene, const NodeBoxes& boxes, int index, int depth) {
    const std::vector<char>& casting = boxes.casting;
    const SceneNode& node = scene.nodes[std::size_t(index)];
    ImGui::PushID(index);
    const bool inheritedOff = node.parent >= 0 && !casting[std::size_t(node.parent)];
    bool casts = casting[std::size_t(index)] != 0;
    ImGui::BeginDisabled(inheritedOff);
    if (ImGui::Checkbox("##casts", &casts)) setExcluded(state, node.path, !casts);
    ImGui::EndDisabled();
    state.controls.recordLastItem("outliner.casts=" + node.path);
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s\n%s", node.path.c_str(),
                          inheritedOff ? "An ancestor casts no shadows: nothing under it does"
                                       : "Casts shadows (unticked: this node and everything under it cast none)");
    ImGui::SameLine();
    if (boxes.statics) {
        bool isStatic = (*boxes.statics)[std::size_t(index)] != 0;
        if (ImGui::Checkbox("##static", &isStatic)) setStatic(state, scene, boxes.playing, index, isStatic);
        state.controls.recordLastItem("outliner.static=" + node.path);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s\n%s", node.path.c_str(),
                              isStatic ? "Static: kept in a cachedStatic light's cached depth (unticked: casters.dynamic,"
                                         " drawn at every update)"
                                       : "Dynamic: drawn at every update of a cachedStatic light (ticked: "
                                         "casters.static; if it moves, the cache is wrong and the frame warns)");
        ImGui::SameLine();
    }
    const std::string label = node.name.empty() ? node.path.substr(node.path.rfind('/') + 1) : node.name;
    // The top two levels start open: a file's structure (root, its groups) shows at once.
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_SpanAvailWidth | (depth < 2 ? ImGuiTreeNodeFlags_DefaultOpen : 0);
    if (node.children.empty()) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
    // Its index as the id and the name as text: a name may hold "##" or '%'.
    const bool open = ImGui::TreeNodeEx(reinterpret_cast<void*>(std::intptr_t(index)), flags, "%s", label.c_str());
    state.controls.recordLastItem("outliner.node=" + node.path);
    if (open && !node.children.empty()) {
        for (int child : node.children) drawNode(state, scene, boxes, child, depth + 1);
        ImGui::TreePop();
    }
    ImGui::PopID();
}

}  // namespace

void drawOutlinerPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    if (!state.scene) return;
    const Scene& scene = *state.scene;
    // Wrapped: the sidebar is narrow at 1280x720.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (scene.nodes.empty()) {
        ImGui::TextWrapped("%s has no node tree (a built-in scene): every mesh casts", scene.name.c_str());
        ImGui::PopStyleColor();
        return;
    }
    const CasterSettings& casters = state.settings.casters;
    const std::vector<char> casting = castingNodes(scene, casters);
    const long off = long(std::count(casting.begin(), casting.end(), 0));
    ImGui::TextWrapped("%zu nodes, %ld cast no shadows (casters.excluded)", scene.nodes.size(), off);
    std::string playError;
    const std::vector<int> playing =
        chosenAnimations(scene, state.settings.animation.play, playError).value_or(std::vector<int>{});
    const bool choosesStatic =
        !scene.animations.empty() || !casters.forcedStatic.empty() || !casters.forcedDynamic.empty();
    const std::vector<char> statics = choosesStatic ? staticNodes(scene, playing, casters) : std::vector<char>{};
    if (choosesStatic) {
        const long moving = long(std::count(statics.begin(), statics.end(), 0));
        ImGui::TextWrapped("boxes: casts, static; %ld dynamic (moved by the playing animations or casters.dynamic)",
                           moving);
    }
    ImGui::PopStyleColor();
    for (const std::string& warning : unknownCasterPathWarnings(scene, state.settings.casters)) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.7f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s", warning.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::BeginChild("##tree", ImVec2(0, 0), false);
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].parent < 0)
            drawNode(state, scene, NodeBoxes{casting, choosesStatic ? &statics : nullptr, playing}, int(i), 0);
    ImGui::EndChild();
}

}  // namespace shadowlab::editor
