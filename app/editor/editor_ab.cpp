// The editor's A/B comparison: A's view rendered beside B's, the toolbar's A/B buttons, the divider and the labels
// (the state and actions are in ab_compare.h).
#include "editor/editor.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace shadowlab::editor {

namespace {

ImTextureID textureId(unsigned id) { return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(id)); }

// A side's label lines in a dark box whose top corner is `corner` (its left corner, or its right one if `alignRight`).
void drawLabelBox(ImDrawList* draw, ImVec2 corner, bool alignRight, const std::vector<std::string>& lines) {
    const float pad = 5.0f, lineHeight = ImGui::GetTextLineHeight();
    float width = 0.0f;
    for (const std::string& line : lines) width = std::max(width, ImGui::CalcTextSize(line.c_str()).x);
    const ImVec2 at(alignRight ? corner.x - width - 2 * pad : corner.x, corner.y);
    draw->AddRectFilled(at, ImVec2(at.x + width + 2 * pad, at.y + float(lines.size()) * lineHeight + 2 * pad),
                        IM_COL32(0, 0, 0, 190), 3.0f);
    for (std::size_t i = 0; i < lines.size(); ++i)
        draw->AddText(ImVec2(at.x + pad, at.y + pad + float(i) * lineHeight),
                      i == 0 ? IM_COL32(255, 255, 255, 255) : IM_COL32(210, 210, 210, 255), lines[i].c_str());
}

}  // namespace

void Editor::renderAbView() {
    if (!state_.ab.active || !state_.scene || !orbit_) return;
    const int w = int(viewportRect_.z), h = int(viewportRect_.w);
    if (w < 16 || h < 16 || target_.width() != w || target_.height() != h) return;
    rememberMeasurement(state_.ab, state_.accuracy);
    if (state_.accuracy.overlayShown()) return;  // the overlay hides both views
    abRenderer_.render(state_, previewed(abSettingsA(state_)), orbit_->toCamera(), w, h,
                       state_.showLightFrustum ? frustum_.get() : nullptr);
}

bool Editor::abViewDue() const {
    if (!state_.ab.active || !state_.scene || !orbit_) return false;
    if (state_.accuracy.overlayShown()) return false;
    const int w = int(viewportRect_.z), h = int(viewportRect_.w);
    if (w < 16 || h < 16 || target_.width() != w || target_.height() != h) return false;  // B renders first
    return abRenderer_.due(state_, previewed(abSettingsA(state_)), orbit_->toCamera(), w, h, state_.showLightFrustum);
}

void Editor::abToolbar() {
    if (!state_.ab.active) {
        if (ImGui::Button("A/B")) startAb(state_);
        state_.controls.recordLastItem("ab.start");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Compare: keep the current settings as A and go on editing B; the view shows A left of a "
                              "draggable divider and B right of it, each with its pass times and accuracy");
        return;
    }
    // While comparing, one highlighted button opens the rest (the toolbar has no room for three more).
    ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::Button("A/B ...")) ImGui::OpenPopup("abMenu");
    ImGui::PopStyleColor();
    state_.controls.recordLastItem("ab.menu");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Comparing A (left) with the edited B (right): swap, apply A or stop");
    if (!ImGui::BeginPopup("abMenu")) return;
    if (ImGui::Selectable("Swap A and B")) swapAb(state_);
    state_.controls.recordLastItem("ab.swap");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A and B trade settings: you then edit the former A");
    if (ImGui::Selectable("Apply A")) applyA(state_);
    state_.controls.recordLastItem("ab.applyA");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The edited settings (B) become A's: %s", state_.ab.aName.c_str());
    if (ImGui::Selectable("Stop comparing")) stopAb(state_);
    state_.controls.recordLastItem("ab.stop");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to one view; the edited settings (B) stay");
    ImGui::EndPopup();
}

void Editor::abDividerInput(ImVec2 imagePos, ImVec2 imageSize) {
    if (!state_.ab.active || !state_.ab.haveStatsA || imageSize.x < 16.0f || imageSize.y < 16.0f) return;
    constexpr float kGrab = 12.0f;  // the divider's grab width in pixels
    const float x = imagePos.x + std::floor(state_.ab.divider * imageSize.x);
    ImGui::SetCursorScreenPos(ImVec2(x - kGrab * 0.5f, imagePos.y));
    ImGui::InvisibleButton("##abDivider", ImVec2(kGrab, imageSize.y));
    state_.controls.recordLastItem("ab.divider");
    if (ImGui::IsItemHovered() || ImGui::IsItemActive()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    if (ImGui::IsItemActive() && ImGui::GetIO().MouseDelta.x != 0.0f)
        state_.ab.divider = std::clamp((ImGui::GetIO().MousePos.x - imagePos.x) / imageSize.x, 0.0f, 1.0f);
}

bool Editor::drawAbSplit(ImVec2 imagePos, ImVec2 imageSize) {
    const RenderTarget& a = abRenderer_.target();
    if (!state_.ab.active || !state_.ab.haveStatsA || a.width() != target_.width() || a.height() != target_.height())
        return false;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float f = std::clamp(state_.ab.divider, 0.0f, 1.0f);
    const float x = imagePos.x + std::floor(f * imageSize.x);
    const ImVec2 end(imagePos.x + imageSize.x, imagePos.y + imageSize.y);
    // Both targets have GL's bottom row first: v runs from 1 at the top to 0 at the bottom.
    draw->AddImage(textureId(a.colorTexture()), imagePos, ImVec2(x, end.y), ImVec2(0, 1), ImVec2(f, 0));
    draw->AddImage(textureId(target_.colorTexture()), ImVec2(x, imagePos.y), end, ImVec2(f, 1), ImVec2(1, 0));
    draw->AddLine(ImVec2(x, imagePos.y), ImVec2(x, end.y), IM_COL32(0, 0, 0, 200), 4.0f);
    draw->AddLine(ImVec2(x, imagePos.y), ImVec2(x, end.y), IM_COL32(255, 255, 255, 255), 2.0f);
    draw->AddCircleFilled(ImVec2(x, imagePos.y + imageSize.y * 0.5f), 7.0f, IM_COL32(255, 255, 255, 255));
    const std::optional<AccuracyViewKey> now = accuracyKey();
    drawLabelBox(draw, ImVec2(imagePos.x + 6.0f, imagePos.y + 6.0f), false, abLabel(state_, true, now));
    drawLabelBox(draw, ImVec2(end.x - 6.0f, imagePos.y + 6.0f), true, abLabel(state_, false, now));
    return true;
}

}  // namespace shadowlab::editor
