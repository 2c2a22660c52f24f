// Stats: per-pass times (labelled CPU on a software rasterizer), why the shadow pass ran, frame-time history,
// triangles, casters and shadow-map memory; a table of the shadow views (ran or skipped, why, memory, time).
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "shading/filters/filter_technique.h"
#include "editor/view_rows.h"
#include "shadow/shadow_map.h"

#include <cstdio>

#include <algorithm>
#include <vector>

namespace shadowlab::editor {

namespace {

// "shadow pass  4.37 ms CPU  ran: bias changed"; a skipped pass shows its last time and why it was skipped.
void passLine(const char* name, const PassStats& pass, const PassStats& lastRun, const char* clock) {
    const PassStats& timed = pass.ran ? pass : lastRun;
    if (timed.milliseconds)
        ImGui::Text("%-12s %7.2f ms %s", name, *timed.milliseconds, clock);
    else
        ImGui::Text("%-12s %10s", name, "-");
    // Why it ran: beside the time where it fits, else on the next line.
    const std::string why = std::string(pass.ran ? "ran: " : "skipped: ") + pass.reason.substr(0, pass.reason.find(':'));
    ImGui::SameLine();
    const bool below = ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(why.c_str()).x;
    if (below) {
        ImGui::NewLine();
        ImGui::Indent();
    }
    noteText(why);
    if (below) ImGui::Unindent();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", pass.reason.c_str());
}

void plot(const char* label, const std::deque<float>& values, ImVec2 size) {
    std::vector<float> v(values.begin(), values.end());
    const float top = v.empty() ? 1.0f : std::max(1.0f, *std::max_element(v.begin(), v.end()) * 1.15f);
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%s (max %.1f ms)", label, double(top / 1.15f));
    ImGui::PlotLines("##plot", v.data(), int(v.size()), 0, overlay, 0.0f, top, size);
}

// One row per shadow view of the frame (each cube face, each cascade marked with its colour): what its map got (reused,
// static + dynamic, full), its map's memory and its time, with the planner's reason on the line below, wrapped at the panel's edge. Columns are as
// wide as their widest cell and the reason has the panel's whole width, so nothing is cut in a narrow sidebar (a table
// gave the reason a sliver beside cascade names).
void viewsTable(EditorState& state) {
    const std::vector<ViewRow> rows = viewRows(state.stats, state.viewMilliseconds);
    if (rows.empty()) {
        ImGui::TextDisabled("shadow views: none (no lights)");
        return;
    }
    const ImGuiStyle& style = ImGui::GetStyle();
    const char* msHeader = "ms";  // CPU or GPU: the timing line above says which (the column stays narrow)
    const float swatch = ImGui::GetTextLineHeight() * 0.8f + style.ItemInnerSpacing.x;  // cascadeSwatch's width
    float nameW = ImGui::CalcTextSize("view").x, passW = ImGui::CalcTextSize("static + dynamic").x;
    float memoryW = ImGui::CalcTextSize("memory").x, msW = ImGui::CalcTextSize(msHeader).x;
    for (const ViewRow& row : rows) {
        nameW = std::max(nameW, (row.cascade >= 0 ? swatch : 0.0f) + ImGui::CalcTextSize(row.name.c_str()).x);
        memoryW = std::max(memoryW, ImGui::CalcTextSize(row.memory.c_str()).x);
        msW = std::max(msW, ImGui::CalcTextSize(row.milliseconds.c_str()).x);
    }
    const float gap = 2.0f * style.ItemSpacing.x;
    const float x0 = ImGui::GetCursorPosX();
    const float xPass = x0 + nameW + gap, xMemory = xPass + passW + gap, xMs = xMemory + memoryW + gap;
    ImGui::BeginGroup();
    ImGui::TextDisabled("view");
    ImGui::SameLine(xPass);
    ImGui::TextDisabled("update");
    ImGui::SameLine(xMemory);
    ImGui::TextDisabled("memory");
    ImGui::SameLine(xMs);
    ImGui::TextDisabled("%s", msHeader);
    ImGui::Separator();
    for (const ViewRow& row : rows) {
        if (row.cascade >= 0) cascadeSwatch(row.cascade);
        ImGui::TextUnformatted(row.name.c_str());
        state.controls.recordLastItem("stats.view=" + row.name);
        ImGui::SameLine(xPass);
        if (row.ran)
            ImGui::TextUnformatted(row.update.c_str());
        else
            ImGui::TextDisabled("%s", row.update.c_str());
        ImGui::SameLine(xMemory);
        ImGui::TextUnformatted(row.memory.c_str());
        ImGui::SameLine(xMs);
        if (row.timeFromEarlier || row.milliseconds == "-")
            ImGui::TextDisabled("%s", row.milliseconds.c_str());
        else
            ImGui::TextUnformatted(row.milliseconds.c_str());
        if (row.timeFromEarlier && ImGui::IsItemHovered())
            ImGui::SetTooltip("its newest run's time (this frame kept its map)");
        ImGui::Indent();
        noteText(row.why);
        ImGui::Unindent();
    }
    ImGui::EndGroup();
    state.controls.recordLastItem("stats.views");
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

    // A sidebar's column: the numbers (long lines wrap), the views table, then the two plots one above the other.
    const FrameStats& shadow = state.lastShadowPass;
    passLine("shadow pass", s.shadowPass, shadow.shadowPass, clock);
    passLine("main pass", s.mainPass, s.mainPass, clock);
    // A moments technique's own cost lines: the conversion, the blur and the mips (they run only when a view's map changed).
    if (filterTechnique(state.settings.filter.kind).moments) {
        passLine("moments", s.momentsPass, s.momentsPass, clock);
        passLine("blur", s.blurPass, s.blurPass, clock);
        if (state.settings.filter.momentMips) passLine("mips", s.mipsPass, s.mipsPass, clock);
    }
    if (const FilterTechnique& t = filterTechnique(state.settings.filter.kind); t.cost)
        ImGui::TextWrapped("%s", t.cost(state.settings.filter).c_str());  // its lookup's share of the main pass
    if (s.depthBoundsPass.ran) {
        passLine("depth bounds", s.depthBoundsPass, s.depthBoundsPass, clock);
        if (s.seenDepths && s.seenDepths->farthest >= s.seenDepths->nearest)
            noteText("seen depths " + std::to_string(s.seenDepths->nearest) + ".." + std::to_string(s.seenDepths->farthest));
    }
    ImGui::Text("frame        %7.2f ms wall", state.lastFrameMs);
    noteText("timing: " + s.timingSource);
    ImGui::TextWrapped("triangles: %zu scene, %zu in the shadow pass", s.sceneTriangles, shadow.shadowTriangles);
    ImGui::TextWrapped("casters: %d drawn in %d draw calls, %d outside the light, %d alpha-tested",
                       shadow.castersDrawn, shadow.shadowDrawCalls, shadow.castersSkipped, shadow.alphaTestedCasters);
    if (s.sceneUpload.ran) noteText("scene: " + s.sceneUpload.reason);
    ImGui::TextWrapped("shadow map: %d² %s, %.1f MiB", s.shadowMapResolution, depthFormatName(s.shadowMapFormat),
                       double(s.shadowMapBytes) / (1024.0 * 1024.0));
    noteText("frames rendered " + std::to_string(state.renderedFrames) + ", idle frames (no pass) " +
             std::to_string(state.idleFrames));
    state.controls.recordLastItem("stats.frames");
    viewsTable(state);

    const float w = ImGui::GetContentRegionAvail().x;
    const float h = std::clamp((ImGui::GetContentRegionAvail().y - ImGui::GetStyle().ItemSpacing.y) * 0.5f, 30.0f, 160.0f);
    ImGui::PushID("frame");
    plot("frame ms", state.history.frameMs, ImVec2(w, h));
    ImGui::PopID();
    ImGui::PushID("shadow");
    plot("shadow pass ms", state.history.shadowPassMs, ImVec2(w, h));
    ImGui::PopID();
}

}  // namespace shadowlab::editor
