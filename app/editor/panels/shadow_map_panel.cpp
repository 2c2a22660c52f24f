// Shadow map: resolution (quick picks + custom, capped at GL_MAX_TEXTURE_SIZE), depth format, reversed-Z, the three
// D3D bias values, normal offset, receiver-plane bias and cull mode; beside the bias, what it amounts to in depth
// steps, texels and world units.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "shadow/shadow_map.h"

#include <algorithm>
#include <string>

namespace shadowlab::editor {

namespace {

void resolutionControls(EditorState& state) {
    static constexpr struct {
        const char* label;
        int size;
    } kPicks[] = {{"256", 256}, {"512", 512}, {"1K", 1024}, {"2K", 2048}, {"4K", 4096}, {"8K", 8192}};
    const int current = state.selected()->shadow.resolution;
    const std::string key = state.lightKey("shadow.resolution");
    const int maxSize = state.limits.maxTextureSize;
    ImGui::TextUnformatted("resolution");
    for (const auto& pick : kPicks) {
        ImGui::SameLine();
        const bool selected = pick.size == current;
        const bool tooBig = maxSize > 0 && pick.size > maxSize;
        if (selected) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        ImGui::BeginDisabled(tooBig);
        if (ImGui::SmallButton(pick.label) && !selected) state.edit(key, pick.size);
        ImGui::EndDisabled();
        if (selected) ImGui::PopStyleColor();
        state.controls.recordLastItem(std::string("shadow.resolution=") + pick.label);
        if (tooBig && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("above this GPU's GL_MAX_TEXTURE_SIZE (%d)", maxSize);
    }
    int custom = current;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
    if (ImGui::InputInt("custom (Enter)", &custom, 0, 0, ImGuiInputTextFlags_EnterReturnsTrue) && custom != current)
        state.edit(key, custom);
    state.controls.recordLastItem("shadow.resolution");
    fieldHelp(state, key.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("max %d", maxSize);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("GL_MAX_TEXTURE_SIZE of this GPU");
    showFieldError(state, key.c_str());
    const std::vector<const ShadowViewStats*> views = state.selectedLightViews();
    if (!views.empty())
        ImGui::TextDisabled("map: %d x %d %s%s; all maps %.1f MiB", views.front()->resolution,
                            views.front()->resolution, depthFormatName(views.front()->format),
                            views.size() > 1 ? " per face" : "", double(state.stats.shadowMapBytes) / (1024.0 * 1024.0));
}

void biasAmounts(const EditorState& state) {
    if (!state.haveStats) return;
    // The frame reports the bias of its first view only.
    const auto first = std::find_if(state.stats.views.begin(), state.stats.views.end(),
                                    [](const ShadowViewStats& v) { return v.hasView; });
    if (first == state.stats.views.end() || first->light != state.selectedLight) return;
    // The bias at this scene's receivers, each term in depth, world units and texels; the frame report's full
    // sentences (what r is, at which depths) in the tooltip.
    const BiasReport& b = state.stats.bias;
    auto row = [](const char* term, const BiasTerm& t) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextDisabled("%s", term);
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", t.depth);
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", t.world);
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", t.texels);
    };
    if (ImGui::BeginTable("bias amounts", 4, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
        for (const char* header : {"bias at receivers", "depth", "world", "texels"}) ImGui::TableSetupColumn(header);
        ImGui::TableHeadersRow();
        const bool varies = b.constantNear.depth != b.constantFar.depth || b.constantNear.world != b.constantFar.world;
        row(varies ? "DepthBias, nearest" : "DepthBias", b.constantNear);
        if (varies) row("DepthBias, farthest", b.constantFar);
        row("slope-scaled (median)", b.slope);
        if (b.shadow.depthBiasClamp > 0.0f) row("clamp", b.clamp);
        row("total (median)", b.total);
        row("clip-space precision", b.clipPrecision);  // a total below it cannot beat the rounding: acne
        ImGui::EndTable();
    }
    if (ImGui::IsItemHovered()) {
        std::string text;
        for (const std::string& line : describeBias(b)) text += line + "\n";
        ImGui::SetTooltip("%s", text.c_str());
    }
    ImGui::TextDisabled("normal offset = %.3g world units (texel %.3g)", b.normalOffsetWorld, b.texelWorldSize);
}

}  // namespace

void drawShadowMapPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    if (!lightHeader(state)) return;
    auto key = [&](const char* within) { return state.lightKey(within); };
    resolutionControls(state);
    ImGui::PushItemWidth(-175.0f);
    comboField(state, key("shadow.depthFormat").c_str(), "depth format");
    ImGui::Separator();
    dragFloatField(state, key("shadow.depthBias").c_str(), "DepthBias (units)", 1.0f, "%.4g");  // d16 after a format change: 0.0078
    sliderFloatField(state, key("shadow.slopeScaledDepthBias").c_str(), "SlopeScaledDepthBias", 0.0f, 10.0f, "%.2f");
    dragFloatField(state, key("shadow.depthBiasClamp").c_str(), "DepthBiasClamp", 0.0001f, "%.5f");
    sliderFloatField(state, key("shadow.normalOffset").c_str(), "normal offset (texels)", 0.0f, 4.0f, "%.2f");
    checkboxField(state, key("shadow.receiverPlaneBias").c_str(), "receiver-plane bias (PCF, Poisson)");
    biasAmounts(state);
    ImGui::Separator();
    comboField(state, key("shadow.cullMode").c_str(), "cull (shadow pass)");
    checkboxField(state, key("shadow.reversedZ").c_str(), "Reversed-Z (near 1, far 0)");
    ImGui::Separator();
    comboField(state, key("shadow.update").c_str(), "update (moving scenes)");
    if (state.settings.lights[state.selectedLight].shadow.update == ShadowUpdate::EveryNthFrame)
        comboField(state, key("shadow.updateInterval").c_str(), "every N frames");
    ImGui::PopItemWidth();
}

}  // namespace shadowlab::editor
