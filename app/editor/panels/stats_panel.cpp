// Stats: per-pass times (labelled CPU on a software rasterizer), why the shadow pass ran, frame-time history,
// triangles, casters and shadow-map memory.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "shadow/shadow_map.h"

#include <cstdio>

#include <algorithm>
#include <vector>

namespace shadowlab::editor {

namespace {

void passLine(const char* name, const PassStats& pass, const char* clock) {
    if (pass.milliseconds)
        ImGui::Text("%-12s %7.2f ms %s", name, *pass.milliseconds, clock);
    else
        ImGui::Text("%-12s %10s", name, "-");
    ImGui::SameLine();
    ImGui::TextDisabled("%s: %s", pass.ran ? "ran" : "skipped", pass.reason.c_str());
}

void plot(const char* label, const std::deque<float>& values, ImVec2 size) {
    std::vector<float> v(values.begin(), values.end());
    const float top = v.empty() ? 1.0f : std::max(1.0f, *std::max_element(v.begin(), v.end()) * 1.15f);
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%s (max %.1f ms)", label, double(top / 1.15f));
    ImGui::PlotLines("##plot", v.data(), int(v.size()), 0, overlay, 0.0f, top, size);
}

}  // namespace

void drawStatsPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    if (!state.haveStats) {
        ImGui::TextDisabled("no frame rendered yet");
        return;
    }
    const FrameStats& s = state.stats;
    const bool cpu = s.timingSource.rfind("CPU", 0) == 0;
    const char* clock = cpu ? "CPU" : "GPU";

    if (ImGui::BeginTable("stats", 2, ImGuiTableFlags_SizingStretchSame)) {
        ImGui::TableSetupColumn("numbers", ImGuiTableColumnFlags_WidthStretch, 0.6f);
        ImGui::TableSetupColumn("plots", ImGuiTableColumnFlags_WidthStretch, 0.4f);
        ImGui::TableNextColumn();
        passLine("shadow pass", s.shadowPass, clock);
        passLine("main pass", s.mainPass, clock);
        ImGui::Text("frame        %7.2f ms wall", state.lastFrameMs);
        ImGui::TextDisabled("timing: %s", s.timingSource.c_str());
        ImGui::Text("triangles: %zu scene, %zu in shadow pass", s.sceneTriangles, s.shadowTriangles);
        ImGui::Text("casters: %d drawn, %d skipped, %d alpha-tested", s.castersDrawn, s.castersSkipped,
                    s.alphaTestedCasters);
        ImGui::Text("shadow map: %d² %s, %.1f MiB", s.shadowMapResolution, depthFormatName(s.shadowMapFormat),
                    double(s.shadowMapBytes) / (1024.0 * 1024.0));
        ImGui::TextDisabled("frames rendered %ld, idle frames (no pass) %ld", state.renderedFrames, state.idleFrames);
        state.controls.recordLastItem("stats.frames");

        ImGui::TableNextColumn();
        const float w = ImGui::GetContentRegionAvail().x;
        const float h = std::max(30.0f, (ImGui::GetContentRegionAvail().y - 8.0f) * 0.5f);
        ImGui::PushID("frame");
        plot("frame ms", state.history.frameMs, ImVec2(w, h));
        ImGui::PopID();
        ImGui::PushID("shadow");
        plot("shadow pass ms", state.history.shadowPassMs, ImVec2(w, h));
        ImGui::PopID();
        ImGui::EndTable();
    }
}

}  // namespace shadowlab::editor
