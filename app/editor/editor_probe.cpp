// The viewport's pixel probe: a click (press and release without a drag) or P held over a pixel asks; the next
// frame probes it with the editor's own renderer (same shadow map) and, when the Accuracy panel's measurement is of
// this very view, its exact verdict and cause. A changed view or setting probes the same pixel again. Ctrl+drag
// draws a line whose depth profile the Probe panel plots.
#include "accuracy/light_isolation.h"
#include "editor/editor.h"
#include "editor/editor_keys.h"
#include "probe/probe_description.h"
#include "settings/atomic_file.h"

#include <algorithm>
#include <cmath>

namespace shadowlab::editor {

void Editor::probeViewportInput(ImVec2 imagePos) {
    const ImGuiIO& io = ImGui::GetIO();
    // ImGui keeps -FLT_MAX as the position while it knows none (before the first move, or the mouse out of the
    // window): converting that to int is undefined, so an unknown position is the pixel (-1, -1), outside the view.
    const bool known = ImGui::IsMousePosValid(&io.MousePos);
    const int x = known ? int(std::floor(io.MousePos.x - imagePos.x)) : -1;
    const int y = known ? int(std::floor(io.MousePos.y - imagePos.y)) : -1;
    ProbeState& line = state_.probe;
    // Ctrl+drag draws the depth profile's line, from the press to the cursor, both clamped to the view.
    const int lastX = int(viewportRect_.z) - 1, lastY = int(viewportRect_.w) - 1;
    if (ImGui::IsItemActive() && io.MouseDown[0] && io.KeyCtrl && io.MouseDragMaxDistanceSqr[0] >= 9.0f) {
        line.lineFrom = glm::ivec2(std::clamp(int(std::floor(io.MouseClickedPos[0].x - imagePos.x)), 0, lastX),
                                   std::clamp(int(std::floor(io.MouseClickedPos[0].y - imagePos.y)), 0, lastY));
        line.lineTo = glm::ivec2(std::clamp(x, 0, lastX), std::clamp(y, 0, lastY));
        line.drawingLine = true;
    }
    if (line.drawingLine && !io.MouseDown[0]) {
        line.drawingLine = false;
        line.profileRequested = true;
        return;
    }
    if (x < 0 || y < 0 || x >= int(viewportRect_.z) || y >= int(viewportRect_.w)) return;
    const glm::ivec2 pixel(x, y);
    // A left click that did not move (a drag orbits instead); Shift+click pans.
    const bool click = ImGui::IsItemDeactivated() && io.MouseReleased[0] && !io.KeyShift && !io.KeyAlt &&
                       io.MouseDragMaxDistanceSqr[0] < 9.0f;  // Alt+click sets the orbit's pivot
    const bool held = ImGui::IsItemHovered() && io.KeysDown[keys::kP] && !io.WantTextInput;
    const ProbeState& p = state_.probe;
    const bool samePixel = p.report && p.report->x == x && p.report->y == y;
    if (click || (held && !samePixel)) {
        state_.probe.request = pixel;
        state_.showPanel = "Probe";  // its answer is in the Probe tab
    }
}

void Editor::drawProbeMarker(ImVec2 imagePos) {
    const ProbeState& p = state_.probe;
    if (!p.report) return;
    const ImVec2 c(imagePos.x + float(p.report->x) + 0.5f, imagePos.y + float(p.report->y) + 0.5f);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddCircle(c, 7.0f, IM_COL32(0, 0, 0, 200), 16, 3.0f);
    draw->AddCircle(c, 7.0f, IM_COL32(255, 230, 0, 255), 16, 1.5f);
}

void Editor::drawProfileLine(ImVec2 imagePos) {
    const ProbeState& p = state_.probe;
    if (!p.lineFrom || !p.lineTo) return;
    const ImVec2 a(imagePos.x + float(p.lineFrom->x) + 0.5f, imagePos.y + float(p.lineFrom->y) + 0.5f);
    const ImVec2 b(imagePos.x + float(p.lineTo->x) + 0.5f, imagePos.y + float(p.lineTo->y) + 0.5f);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddLine(a, b, IM_COL32(0, 0, 0, 200), 3.0f);
    draw->AddLine(a, b, IM_COL32(0, 220, 255, 255), 1.5f);
    draw->AddCircleFilled(a, 3.0f, IM_COL32(0, 220, 255, 255));
}

std::string Editor::captureProbe(const AccuracyViewKey& key) {
    // The selected light alone: the probe explains that light's S, never light 0's or the lights' mean.
    std::string error;
    const std::optional<Settings> one = isolateLight(key.settings, *key.scene, key.light, error);
    if (!one) return error;
    return probe_->capture(*renderer_, *key.scene, *one, key.camera, key.width, key.height, key.light);
}

void Editor::runProfile() {
    ProbeState& p = state_.probe;
    const std::optional<AccuracyViewKey> key = accuracyKey();
    if (!key || !renderer_ || !p.lineFrom || !p.lineTo || p.drawingLine) return;
    const bool follow = p.profile && p.profileKey && !(*p.profileKey == *key) && !ImGui::IsAnyMouseDown();
    if (!p.profileRequested && !follow) return;
    p.profileRequested = false;
    if (!probe_) probe_ = std::make_unique<PixelProbe>();
    DepthProfile profile;
    if (std::string error = captureProbe(*key);
        !error.empty())
        profile.error = error;
    else
        profile = depthProfile(*probe_, *p.lineFrom, *p.lineTo);
    p.profile = std::move(profile);
    p.profileKey = key;
}

void Editor::runProbe() {
    ProbeState& p = state_.probe;
    const std::optional<AccuracyViewKey> key = accuracyKey();
    if (!key || !renderer_) return;
    std::optional<glm::ivec2> pixel = p.request;
    // The panel's view choice follows the light (another light, kind or cascade count: all views again).
    followLight(p.view, key->light, viewNamesOf(state_, key->light));
    // Follow edits and another view choice live, but not during a drag (an orbit would re-probe every frame).
    if (!pixel && p.report && p.key && (!(*p.key == *key) || p.probedView != p.view.view) && !ImGui::IsAnyMouseDown())
        pixel = glm::ivec2(p.report->x, p.report->y);
    if (!pixel) return;
    p.request.reset();
    if (!probe_) probe_ = std::make_unique<PixelProbe>();
    const AccuracyState& a = state_.accuracy;
    // A live count carries no per-pixel data: only a full measure of this view can explain the pixel.
    const bool measuredHere = a.report && !a.report->live && a.reportKey && *a.reportKey == *key;
    PixelProbeReport report;
    std::string error = captureProbe(*key);
    std::optional<std::size_t> view;  // the chosen view, found as the CLI's --view finds it
    if (error.empty() && !p.view.view.empty()) view = findView(probe_->views(), p.view.view, error);
    if (!error.empty()) {
        report.x = pixel->x;
        report.y = pixel->y;
        report.error = error;
    } else {
        report = probe_->at(pixel->x, pixel->y, measuredHere ? &*a.report : nullptr, view);
    }
    p.report = std::move(report);
    p.key = key;
    p.probedView = p.view.view;
    p.withMeasurement = measuredHere;
}

void Editor::saveProbeJson() {
    const ProbeState& p = state_.probe;
    if (!p.report) {
        state_.say("probe: nothing to save yet (click a pixel in the view)", true);
        return;
    }
    nlohmann::json json = probeToJson(*p.report);
    json["scene"] = state_.sceneSpec;
    json["preset"] = state_.preset.name();
    const std::string path = stampedPath(state_.screenshotDir, "probe", ".json");
    if (std::string error = writeFileAtomically(path, json.dump(2) + "\n"); !error.empty()) {
        state_.say("probe not saved: " + error, true);
        return;
    }
    state_.say("probe: " + path);
}

}  // namespace shadowlab::editor
