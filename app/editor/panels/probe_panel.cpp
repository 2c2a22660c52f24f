// Probe: why the clicked viewport pixel is lit or shadowed — the probe's report in words (probe_description.h),
// with the headline coloured by whether the CPU's S and the GPU's agree. The Shadow map viewer highlights the taps.
// Above it, once a line is Ctrl+dragged in the viewport, the depth profile along it (depth_profile.h).
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "editor/view_choice.h"
#include "probe/probe_description.h"

#include <algorithm>
#include <limits>

namespace shadowlab::editor {

namespace {

// Receiver depth, receiver - bias and the map's texels - bias on one scale, drawn over each other (as the CLI's
// chart: the staircase below the orange line is where the comparison says shadowed), and the acne / Peter Panning
// counts.
void drawProfileSection(EditorState& state) {
    const ProbeState& p = state.probe;
    if (!p.profile) return;
    const DepthProfile& profile = *p.profile;
    if (!ImGui::CollapsingHeader("Profile", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (!profile.ok) {
        errorText("depth profile: " + profile.error);
        state.controls.recordLastItem("probe.profile");
        return;
    }
    float low = std::numeric_limits<float>::max(), high = -low;
    for (const ProfileSample& s : profile.samples)
        if (s.surface)
            for (double v : {s.receiver, s.threshold, s.stored - s.bias})
                low = std::min(low, float(v)), high = std::max(high, float(v));
    const float margin = std::max((high - low) * 0.05f, 1e-7f);
    // Background samples sit on the plot's floor (PlotLines has no gaps).
    std::vector<float> receiver, threshold, stored;
    for (const ProfileSample& s : profile.samples) {
        receiver.push_back(s.surface ? float(s.receiver) : low - margin);
        threshold.push_back(s.surface ? float(s.threshold) : low - margin);
        stored.push_back(s.surface ? float(s.stored - s.bias) : low - margin);
    }
    ImGui::TextWrapped("%d,%d -> %d,%d: %d acne, %d Peter Panning of %d surface samples", profile.from.x, profile.from.y,
                profile.to.x, profile.to.y, profile.acne, profile.peterPanning, profile.surfaces);
    state.controls.recordLastItem("probe.profile");
    if (low > high) return;
    const ImVec2 size(ImGui::GetContentRegionAvail().x, 110.0f);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const std::pair<const std::vector<float>*, ImVec4> series[] = {
        {&receiver, ImVec4(0.16f, 0.35f, 0.86f, 1.0f)},
        {&threshold, ImVec4(0.9f, 0.51f, 0.0f, 1.0f)},
        {&stored, ImVec4(0.85f, 0.85f, 0.85f, 1.0f)}};
    for (std::size_t k = 0; k < 3; ++k) {
        ImGui::SetCursorScreenPos(at);
        ImGui::PushStyleColor(ImGuiCol_PlotLines, series[k].second);
        if (k > 0) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0, 0, 0, 0));
        ImGui::PlotLines(("##profile" + std::to_string(k)).c_str(), series[k].first->data(),
                         int(series[k].first->size()), 0, nullptr, low - margin, high + margin, size);
        ImGui::PopStyleColor(k > 0 ? 2 : 1);
    }
    state.controls.recordLastItem("probe.profilePlot");
    ImGui::TextColored(ImVec4(0.16f, 0.45f, 0.95f, 1.0f), "receiver");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.9f, 0.51f, 0.0f, 1.0f), "receiver - bias");
    ImGui::TextWrapped("grey: map texel - bias; below the orange line = shadowed");
}

// Which light and view the report's numbers describe: the view chosen, or (all views) the one holding the pixel and,
// in a cascade's blend band, the cascade it is mixed with.
std::string describedView(const PixelProbeReport& r) {
    std::string text = "numbers of " + r.viewName;
    if (r.viewChosen) return text + " (the view chosen above)";
    text += " (all views: the one holding this pixel";
    for (const PixelProbeReport& next : r.blend) text += ", blended with " + next.cascade;
    return text + ")";
}

}  // namespace

void drawProbePanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    ProbeState& p = state.probe;
    drawViewChoice(state, p.view, state.selectedLight, "probe.view");
    drawProfileSection(state);
    if (!p.report) {
        ImGui::TextWrapped("Click a pixel in the viewport (or hold P over it) to see why it is lit or shadowed: its "
                           "texel, every filter tap's stored depth, the bias terms and the shadow factor. Ctrl+drag "
                           "a line for its depth profile.");
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
    // Wrapped: the summary names the light and both factors, longer than a sidebar is wide.
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("pixel %d,%d: %s", r.x, r.y, probeSummary(r).c_str());
    ImGui::PopStyleColor();
    state.controls.recordLastItem("probe.summary");
    if (r.viewCount >= 2) {  // a one-view light: the summary already names it
        ImGui::TextWrapped("%s", describedView(r).c_str());
        state.controls.recordLastItem("probe.describedView");
    }
    if (ImGui::SmallButton("Save JSON")) ctx.actions.saveProbeJson();
    state.controls.recordLastItem("probe.saveJson");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Writes this report as JSON (as `shadowlab probe --json`) into %s/", state.screenshotDir.c_str());
    if (!p.withMeasurement)
        noteText("(Measure in the Accuracy panel adds the exact visibility and the cause)");
    ImGui::Separator();
    ImGui::BeginChild("##probeLines", ImVec2(0, 0), false);
    const std::vector<std::string> lines = describeProbe(r);
    for (std::size_t i = 1; i < lines.size(); ++i) ImGui::TextWrapped("%s", lines[i].c_str());  // nothing cut
    ImGui::EndChild();
    state.controls.recordLastItem("probe.lines");
}

}  // namespace shadowlab::editor
