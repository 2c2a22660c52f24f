// Cost vs accuracy: `shadowlab sweep` in the editor. Up to three axes of preset keys with their values, run on a
// worker thread (its own GL context) for this view — camera, viewport size and the current settings as the base —
// with progress and Cancel; the chart (the same LinePlot the CLI writes as PNG) fills in as points arrive; hovering a
// point shows its settings and numbers, clicking it applies its axis values through the key table (the preset shows
// `*`); the current settings are ringed where they sit on the axes, and the ring moves as you edit.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "gl/gl.h"
#include "settings/settings_fields.h"
#include "sweep/sweep_output.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace shadowlab::editor {

namespace {

// The values a new axis starts with: every choice of an enum or a restricted integer, map sizes for the resolution,
// else the current value (the user types the rest).
std::string defaultValues(const EditorState& state, const SettingsField& field) {
    if (field.lightKey() == "shadow.resolution") return "512,1024,2048,4096";
    std::string text;
    if (field.kind == SettingsFieldKind::Enum)
        for (const std::string& c : field.choices) text += (text.empty() ? "" : ",") + c;
    else if (!field.intChoices.empty())
        for (int c : field.intChoices) text += (text.empty() ? "" : ",") + std::to_string(c);
    else
        text = sweepValueText(state.settings, field.key);
    return text;
}

void axisRow(EditorState& state, int index) {
    SweepAxisChoice& axis = state.sweep.axes[std::size_t(index)];
    ImGui::PushID(index);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 13.0f);
    if (ImGui::BeginCombo("##key", axis.key.empty() ? "(no axis)" : axis.key.c_str())) {
        if (ImGui::Selectable("(no axis)", axis.key.empty())) axis = {};
        for (const SettingsField* entry : settingsFieldsOf(state.settings)) {
            const SettingsField& field = *entry;
            if (field.group() == "camera" || field.key == "view") continue;  // not a shadow setting
            if (ImGui::Selectable(field.key.c_str(), axis.key == field.key) && axis.key != field.key)
                axis = {field.key, defaultValues(state, field)};
            state.controls.recordLastItem("sweep.axis" + std::to_string(index) + "=" + field.key);
        }
        ImGui::EndCombo();
    }
    state.controls.recordLastItem("sweep.axis" + std::to_string(index));
    ImGui::SameLine();
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "%s", axis.values.c_str());
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::BeginDisabled(axis.key.empty());
    if (ImGui::InputText("##values", buffer, sizeof buffer)) axis.values = buffer;
    ImGui::EndDisabled();
    state.controls.recordLastItem("sweep.values" + std::to_string(index));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("values, separated by commas (vectors in brackets)");
    ImGui::PopID();
}

void startSweep(PanelContext& ctx) {
    EditorState& state = ctx.state;
    SweepPanelState& s = state.sweep;
    const std::optional<AccuracyViewKey> view = ctx.actions.currentView();
    if (!view || !state.scene) {
        s.error = "sweep: nothing to measure yet (no scene or no viewport)";
        return;
    }
    std::vector<std::string> texts;
    for (const SweepAxisChoice& axis : s.axes)
        if (!axis.key.empty()) texts.push_back(axis.key + "=" + axis.values);
    // Refused here, before any work, with the key table's message.
    SweepPlan plan = planSweep(view->settings, texts);
    if (!plan.error.empty()) {
        s.error = plan.error;
        state.say("sweep: " + plan.error, true);
        return;
    }
    SweepRunOptions options;
    options.width = view->width;
    options.height = view->height;
    options.frames = s.frames;
    options.camera = view->camera;
    const std::size_t points = plan.points.size();
    ctx.actions.keepSession();  // a sweep compiles and allocates for every point: keep the unsaved work first
    if (!s.worker->start(state.scene, view->settings, std::move(plan), options)) {
        s.error = "a sweep is still running (Cancel it first)";
        return;
    }
    s.running = true;
    s.error.clear();
    s.base = view->settings;
    s.result.reset();
    s.chartPoints = 0;
    s.hovered.reset();
    s.status = "sweeping " + std::to_string(points) + " points at " + std::to_string(view->width) + "x" +
               std::to_string(view->height);
}

void pollSweep(EditorState& state) {
    SweepPanelState& s = state.sweep;
    if (!s.running) return;
    if (std::optional<SweepResult> done = s.worker->poll()) {
        s.running = false;
        if (done->ok) {
            char text[160];
            std::snprintf(text, sizeof text, "%zu points in %.1f s; %zu on the front", done->points.size(),
                          done->wallMs / 1000.0, done->front.size());
            s.status = text;
        } else {
            s.status = done->cancelled ? "cancelled: " + std::to_string(done->points.size()) + " points measured"
                                       : "failed";
            if (!done->cancelled) s.error = done->error;
        }
        s.result = std::move(*done);
    } else {
        s.result = s.worker->snapshot();
    }
}

// Where the current settings sit: the point whose axis values they have, when every other setting is the sweep's
// base; else none (points.size()).
std::size_t currentPoint(const EditorState& state, const SweepResult& r) {
    Settings rest = state.settings;
    for (const SweepAxis& axis : r.axes)
        for (const std::string& key : axis.keys)
            if (const SettingsField* field = findSettingsField(key)) field->set(rest, field->get(state.sweep.base));
    if (!(rest == state.sweep.base)) return r.points.size();
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        bool same = true;
        for (std::size_t a = 0; a < r.axes.size() && same; ++a)
            same = r.points[i].values[a] == axisValueText(state.settings, r.axes[a]);
        if (same) return i;
    }
    return r.points.size();
}

void applyPoint(EditorState& state, const SweepResult& r, const SweepPointResult& p) {
    for (std::size_t a = 0; a < r.axes.size(); ++a)
        for (const auto& [key, text] : axisAssignments(r.axes[a], p.values[a])) {
            nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
            if (value.is_discarded()) value = text;
            state.edit(key, value);
        }
    state.say("sweep: applied " + p.label + " (the preset shows * until saved)");
}

void tooltip(const SweepPointResult& p, const SweepResult& r) {
    const AccuracyNumbers& n = p.accuracy;
    ImGui::BeginTooltip();
    ImGui::Text("%s%s", p.label.c_str(), p.onFront ? "  (on the front)" : "");
    for (std::size_t a = 0; a < r.axes.size() && a < p.values.size(); ++a)
        ImGui::TextDisabled("%s = %s", r.axes[a].key.c_str(), p.values[a].c_str());
    ImGui::Separator();
    ImGui::Text("cost %.3f ms = shadow %.3f + main %.3f%s", p.costMs, p.shadowMs, p.mainMs,
                r.softwareRasterizer() ? " (CPU)" : "");
    ImGui::Text("shadow pass %.2fx the bare draw (%.3f ms); map %.1f MiB", p.shadowOverBare, p.bareDrawMs,
                double(p.mapBytes) / (1024.0 * 1024.0));
    ImGui::Text("wrong pixels %.3f %%, mean |S-V| %.4f", n.wrongPercent, n.meanError);
    ImGui::Text("acne %.3f %%, leak %.3f %%", n.acnePercent, n.leakPercent);
    ImGui::Text("edge error %.2f texels = %.3g world = %.1f px", n.edgeErrorP95Texels, n.edgeErrorP95World,
                n.edgeErrorP95ScreenPixels);
    ImGui::TextDisabled("click: apply these values");
    ImGui::EndTooltip();
}

void chart(EditorState& state) {
    SweepPanelState& s = state.sweep;
    if (!s.result || s.result->points.empty()) {
        ImGui::TextDisabled(s.running ? "the chart fills in as points arrive" : "no sweep yet: choose axes and Run");
        return;
    }
    SweepResult shown = *s.result;
    // The ring marks the current settings (moving as they are edited), not the base the sweep started from.
    shown.presetPoint = currentPoint(state, shown);
    if (shown.presetPoint < shown.points.size() || !(state.settings == s.base)) shown.preset.reset();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const int w = std::max(240, int(avail.x)), h = std::max(160, int(avail.y) - 4);
    const LinePlot plot = sweepChart(shown);
    if (!s.chart || s.chartWidth != w || s.chartHeight != h || s.chartPoints != shown.points.size() ||
        s.chartMarker != shown.presetPoint + (shown.preset ? 1000000 : 0)) {
        const PlotImage image = drawLinePlot(plot, w, h);
        if (!s.chart || s.chartWidth != w || s.chartHeight != h) {
            s.chart = gl::createTexture(GL_TEXTURE_2D);
            glTextureStorage2D(s.chart.id(), 1, GL_RGBA8, w, h);
            glTextureParameteri(s.chart.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(s.chart.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            s.chartWidth = w;
            s.chartHeight = h;
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage2D(s.chart.id(), 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
        s.chartPoints = shown.points.size();
        s.chartMarker = shown.presetPoint + (shown.preset ? 1000000 : 0);
    }
    const ImVec2 pos = ImGui::GetCursorScreenPos();
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(s.chart.id())), ImVec2(float(w), float(h)));
    state.controls.recordLastItem("sweep.chart");
    s.hovered.reset();
    if (!ImGui::IsItemHovered()) return;
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const std::size_t at = sweepPointAt(shown, w, h, double(mouse.x - pos.x), double(mouse.y - pos.y), 8.0);
    if (at >= shown.points.size()) return;
    s.hovered = at;
    tooltip(shown.points[at], shown);
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) applyPoint(state, shown, shown.points[at]);
}

}  // namespace

void drawSweepWindow(PanelContext& ctx) {
    EditorState& state = ctx.state;
    SweepPanelState& s = state.sweep;
    pollSweep(state);
    if (!s.open) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.45f), ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(display.x * 0.6f, 900.0f), std::min(display.y * 0.65f, 620.0f)),
                             ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Cost vs accuracy", &s.open)) {
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        state.controls.record("panel:Cost vs accuracy", ControlRect{pos.x, pos.y, size.x, size.y});
        ImGui::BeginDisabled(s.running);
        for (int i = 0; i < SweepPanelState::kMaxAxes; ++i) axisRow(state, i);
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
        ImGui::SliderInt("frames per point", &s.frames, 1, 30);
        state.controls.recordLastItem("sweep.frames");
        ImGui::SameLine();
        if (ImGui::Button("Run")) startSweep(ctx);
        state.controls.recordLastItem("sweep.run");
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("time and measure every combination of the axes in this view (the reference once)");
        ImGui::EndDisabled();
        ImGui::SameLine();
        ImGui::BeginDisabled(!s.running);
        if (ImGui::Button("Cancel")) s.worker->cancel();
        state.controls.recordLastItem("sweep.cancel");
        ImGui::EndDisabled();
        if (s.running) {
            char overlay[200];
            std::snprintf(overlay, sizeof overlay, "%s (%.0f %%)", s.worker->stage().c_str(),
                          double(s.worker->progress()) * 100.0);
            ImGui::ProgressBar(s.worker->progress(), ImVec2(-1.0f, 0.0f), overlay);
        } else if (!s.status.empty()) {
            ImGui::TextDisabled("%s", s.status.c_str());
        }
        if (!s.error.empty()) errorText(s.error);
        chart(state);
    }
    ImGui::End();
}

}  // namespace shadowlab::editor
