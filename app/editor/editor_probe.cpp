// The viewport's pixel probe: a click (press and release without a drag) or P held over a pixel asks; the next
// frame probes it with the editor's own renderer (same shadow map) and, when the Accuracy panel's measurement is of
// this very view, its exact verdict and cause. A changed view or setting probes the same pixel again.
#include "editor/editor.h"
#include "editor/editor_keys.h"

#include <cmath>

namespace shadowlab::editor {

void Editor::probeViewportInput(ImVec2 imagePos) {
    const ImGuiIO& io = ImGui::GetIO();
    const int x = int(std::floor(io.MousePos.x - imagePos.x)), y = int(std::floor(io.MousePos.y - imagePos.y));
    if (x < 0 || y < 0 || x >= int(viewportRect_.z) || y >= int(viewportRect_.w)) return;
    const glm::ivec2 pixel(x, y);
    // A left click that did not move (a drag orbits instead); Shift+click pans.
    const bool click = ImGui::IsItemDeactivated() && io.MouseReleased[0] && !io.KeyShift &&
                       io.MouseDragMaxDistanceSqr[0] < 9.0f;
    const bool held = ImGui::IsItemHovered() && io.KeysDown[keys::kP] && !io.WantTextInput;
    const ProbeState& p = state_.probe;
    const bool samePixel = p.report && p.report->x == x && p.report->y == y;
    if (click || (held && !samePixel)) state_.probe.request = pixel;
}

void Editor::drawProbeMarker(ImVec2 imagePos) {
    const ProbeState& p = state_.probe;
    if (!p.report) return;
    const ImVec2 c(imagePos.x + float(p.report->x) + 0.5f, imagePos.y + float(p.report->y) + 0.5f);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddCircle(c, 7.0f, IM_COL32(0, 0, 0, 200), 16, 3.0f);
    draw->AddCircle(c, 7.0f, IM_COL32(255, 230, 0, 255), 16, 1.5f);
}

void Editor::runProbe() {
    ProbeState& p = state_.probe;
    const std::optional<AccuracyViewKey> key = accuracyKey();
    if (!key || !renderer_) return;
    std::optional<glm::ivec2> pixel = p.request;
    // Follow edits live, but not during a drag (an orbit would re-probe every frame).
    if (!pixel && p.report && p.key && !(*p.key == *key) && !ImGui::IsAnyMouseDown())
        pixel = glm::ivec2(p.report->x, p.report->y);
    if (!pixel) return;
    p.request.reset();
    if (!probe_) probe_ = std::make_unique<PixelProbe>();
    const AccuracyState& a = state_.accuracy;
    const bool measuredHere = a.report && a.reportKey && *a.reportKey == *key;
    PixelProbeReport report;
    if (std::string error = probe_->capture(*renderer_, *key->scene, key->settings, key->camera, key->width,
                                            key->height);
        !error.empty()) {
        report.x = pixel->x;
        report.y = pixel->y;
        report.error = error;
    } else {
        report = probe_->at(pixel->x, pixel->y, measuredHere ? &*a.report : nullptr);
    }
    p.report = std::move(report);
    p.key = key;
    p.withMeasurement = measuredHere;
}

}  // namespace shadowlab::editor
