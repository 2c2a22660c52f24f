// Probe: why the clicked viewport pixel is lit or shadowed — the probe's report in words (probe_description.h),
// with the headline coloured by whether the CPU's S and the GPU's agree. The Shadow map viewer highlights the taps.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "probe/probe_description.h"

namespace shadowlab::editor {

void drawProbePanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    const ProbeState& p = state.probe;
    if (!p.report) {
        ImGui::TextWrapped("Click a pixel in the viewport (or hold P over it) to see why it is lit or shadowed: its "
                           "texel, every filter tap's stored depth, the bias terms and the shadow factor.");
        state.controls.recordLastItem("probe.hint");
        return;
    }
    const PixelProbeReport& r = *p.report;
    if (!r.ok) {
        errorText("pixel " + std::to_string(r.x) + "," + std::to_string(r.y) + ": " + r.error);
        state.controls.recordLastItem("probe.summary");
        return;
    }
    const ImVec4 colour = r.agrees ? ImVec4(0.55f, 0.85f, 0.55f, 1.0f) : ImVec4(1.0f, 0.4f, 0.4f, 1.0f);
    ImGui::TextColored(colour, "pixel %d,%d: %s", r.x, r.y, probeSummary(r).c_str());
    state.controls.recordLastItem("probe.summary");
    if (!p.withMeasurement)
        ImGui::TextDisabled("(Measure in the Accuracy panel adds the exact visibility and the cause)");
    ImGui::Separator();
    ImGui::BeginChild("##probeLines", ImVec2(0, 0), false);
    const std::vector<std::string> lines = describeProbe(r);
    for (std::size_t i = 1; i < lines.size(); ++i) ImGui::TextWrapped("%s", lines[i].c_str());  // nothing cut
    ImGui::EndChild();
    state.controls.recordLastItem("probe.lines");
}

}  // namespace shadowlab::editor
