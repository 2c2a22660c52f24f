// Accuracy: how wrong the shadows are against the exact reference (metrics version 2: acne with its severity, leak,
// wrong pixels, mean error, edge error in texels / world units / screen pixels, k, the coarse-map warning, the
// causes of the wrong pixels with a remedy each, the counts behind them and what the reference cost), measured on
// demand or automatically (Auto: live GPU counts while you edit, a full measure once the view is still); a stale
// line when the numbers no longer describe the view; and Suggest bias: the search's path, its result applied to the
// settings, and Save as preset. Flicker: the view played under a camera or light motion (flicker.h), its figures
// and its overlay.
#include "accuracy/cause_shares.h"
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "settings/settings_fields.h"
#include "shading/filters/filter_technique.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace shadowlab::editor {

namespace {

std::string grouped(std::size_t n) { return groupedCount(n); }

void row(const char* name, const std::string& value, const char* tooltip = nullptr) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    if (tooltip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
    ImGui::TableNextColumn();
    // A stretched value column (the numbers table) wraps at the sidebar's edge; a fixed-fit one sizes to its text.
    if (ImGui::TableGetColumnFlags() & ImGuiTableColumnFlags_WidthStretch)
        ImGui::TextWrapped("%s", value.c_str());
    else
        ImGui::TextUnformatted(value.c_str());
}

// Beside the previous control where an item of `width` fits, else on the next line (the sidebar is narrow).
void sameLineIfFits(float width) {
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

std::string format(const char* fmt, double a, double b = 0.0) {
    char text[128];
    std::snprintf(text, sizeof text, fmt, a, b);
    return text;
}

// The shadow view shows the map's comparison on every surface, also on those facing away from the light, which the
// lighting darkens anyway; the numbers rightly skip them, and say so where they are read.
void facingAwayNote(EditorState& state, const AccuracyCounts& c) {
    if (c.facingAway == 0) return;
    noteText("not counted: " + grouped(c.facingAway) +
             " px facing away from the light (stripes there in the shadow view are unlit anyway)");
    state.controls.recordLastItem("accuracy.facingAway");
}

// A light of size > 0: its numbers against the soft reference (metrics version 3), under the light they describe.
void softNumbers(EditorState& state, const SoftAccuracy& s) {
    if (!s.measured) return;
    const SoftCounts& c = s.counts;
    const PenumbraWidths& w = s.penumbra;
    ImGui::Separator();
    noteText("Light " + std::to_string(s.light) + format(", size %.3g ", s.size) + s.sizeUnit +
             (s.sizeUnit == "degrees" ? " (angular diameter)" : " (radius)") + ", " + std::to_string(s.rays) +
             " rays per pixel: version 3, against the share of rays that reach the light (above: version 2, one "
             "ray to its centre)");
    state.controls.recordLastItem("accuracy.soft.light");
    if (!ImGui::BeginTable("soft", 2, ImGuiTableFlags_SizingFixedFit)) return;
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    row("wrong pixels", format("%.3f %%", s.wrongPercent) + "  (" + grouped(c.wrong) + " of " + grouped(c.measured) + ")",
        "|S - V| >= 0.5 against the soft V, over every measured pixel");
    state.controls.recordLastItem("accuracy.soft.wrong");
    row("mean error", format("%.4f", s.meanError), "mean |S - V| against the soft V over every measured pixel");
    row("bleeding", format("%.3f %%", s.bleedingPercent) + "  (" + grouped(c.bleeding) + " of " + grouped(c.umbra) +
                        " umbra)",
        "pixels in the true umbra (V = 0: no ray reaches the light) that the technique lights (S > 1/255): the VSM leak");
    state.controls.recordLastItem("accuracy.soft.bleeding");
    row("over-darkening", format("%.3f %%", s.overDarkeningPercent) + "  (" + grouped(c.overDarkened) + " of " +
                              grouped(c.fullyLit) + " fully lit)",
        "pixels every ray of which reaches the light (V = 1) that the technique darkens (S < 1 - 1/255): acne, or a "
        "blur that spread a shadow");
    row("penumbra width error", format("%+.3g world = ", w.errorWorld) + format("%+.2f texels", w.errorTexels),
        "the technique's 0.1..0.9 transition width across true edges minus the reference's (median over profiles "
        "across the reference's 0.5 contour; docs/accuracy.md says how a width is measured on pixels)");
    state.controls.recordLastItem("accuracy.soft.penumbra");
    row("penumbra widths", format("technique %.3g, ", w.techniqueWorld) + format("reference %.3g world", w.referenceWorld) +
                               " (" + grouped(c.profiles) + " profiles)",
        "the 0.1..0.9 widths themselves, medians over the same profiles");
    row("soft reference", c.measured && s.tracedRays == 0 ? std::string("reused")
                                                          : grouped(s.tracedRays) + format(" rays in %.1f ms", s.traceMs),
        "the soft reference's rays (reused when the light, its size, the ray count and the view are unchanged)");
    ImGui::EndTable();
}

void numbersTab(EditorState& state, const AccuracyReport& r) {
    const AccuracyCounts& c = r.counts;
    if (!r.coarseMapWarning.empty()) {
        warningText(r.coarseMapWarning);
        state.controls.recordLastItem("accuracy.coarseMap");
    }
    if (ImGui::BeginTable("numbers", 2, ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
        row("acne", format("%.3f %%", r.acnePercent) + "  (" + grouped(c.acne) + " of " + grouped(c.lit) + " lit" +
                        (c.acne ? format(", mean 1-S %.2f)", r.acneSeverity) : ")"),
            "truly lit pixels the tool visibly darkens (S < 1 - 1/255) farther than k texels from the true shadow "
            "boundary; severity = mean 1-S over them");
        state.controls.recordLastItem("accuracy.acne");
        row("leak", format("%.3f %%", r.leakPercent) + "  (" + grouped(c.leak) + " of " + grouped(c.shadowed) +
                        " shadowed)",
            "Peter Panning / light leaking: truly shadowed pixels the tool visibly lights (S > 1/255) beyond k texels");
        row("wrong pixels", format("%.3f %%", r.wrongPercent) + "  (" + grouped(c.wrong) + " of " +
                                grouped(c.measured) + ")",
            "|S - V| >= 0.5 over every measured pixel, edges included: compares maps of any resolution");
        state.controls.recordLastItem("accuracy.wrong");
        row("mean error", format("%.4f", r.meanError), "mean |S - V| over every measured pixel, edges included");
        row("edge error", format("%.2f texels = ", r.edgeErrorP95Texels) + format("%.3g world = ", r.edgeErrorP95World) +
                              format("%.1f px (p95)", r.edgeErrorP95ScreenPixels),
            "95th percentile of the distance to the true boundary over mismatched pixels, in shadow-map texels, "
            "world units and screen pixels");
        row("k", format("%.1f texels", r.kTexels) + format(" (%.3g world)", r.kTexels * r.texelWorldSize),
            "filter radius + 1 texel: mismatches closer than this to a true edge are filter blur, not acne or leak");
        ImGui::EndTable();
    }
    facingAwayNote(state, c);
    softNumbers(state, r.soft);
}

// Why the pixels are wrong: each cause's share of what it explains (acne of acne, leak of leak, wrong of wrong; see
// cause_shares.h), with the remedy.
void causesTab(EditorState& state, const AccuracyReport& r) {
    const AccuracyCounts& c = r.counts;
    if (r.live) {
        ImGui::TextWrapped("Live numbers: the causes need shadow rays and come with the full measure, once the view "
                           "is still (Auto) or on Measure.");
        state.controls.recordLastItem("accuracy.causes");
        return;
    }
    if (c.mismatched == 0) {
        ImGui::TextDisabled("no mismatched pixels: nothing to explain");
        return;
    }
    noteText(grouped(c.acne) + " acne, " + grouped(c.leak) + " leak, " + grouped(c.wrong) + " wrong, " +
             grouped(c.mismatched) + " visibly mismatched pixels");
    facingAwayNote(state, c);
    // One line per cause (colour, name, share), its remedy wrapped below: the panel is often narrow.
    ImGui::BeginGroup();
    for (MismatchCause cause : allCauses()) {
        const std::size_t n = c.causePixels[std::size_t(cause)];
        if (n == 0) continue;
        const CauseInfo& info = causeInfo(cause);
        ImGui::ColorButton(info.key, ImVec4(info.red / 255.0f, info.green / 255.0f, info.blue / 255.0f, 1.0f),
                           ImGuiColorEditFlags_NoTooltip, ImVec2(10, 10));
        ImGui::SameLine();
        ImGui::TextWrapped("%s: %s", info.name, causeShares(r, cause).c_str());
        state.controls.recordLastItem(std::string("accuracy.cause.") + info.key);
        ImGui::Indent();
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", info.remedy);
        ImGui::PopStyleColor();
        ImGui::Unindent();
    }
    ImGui::EndGroup();
    state.controls.recordLastItem("accuracy.causes");
}

void countsTab(const AccuracyReport& r) {
    const AccuracyCounts& c = r.counts;
    if (ImGui::BeginTable("counts", 4, ImGuiTableFlags_SizingFixedFit)) {
        auto pair = [](const char* a, std::size_t va, const char* b, std::size_t vb) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(a);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(grouped(va).c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(b);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(grouped(vb).c_str());
        };
        pair("pixels", c.pixels, "measured", c.measured);
        pair("lit", c.lit, "shadowed", c.shadowed);
        pair("acne", c.acne, "leak", c.leak);
        pair("wrong", c.wrong, "wrong beyond k", c.wrongBeyondK);
        pair("mismatched", c.mismatched, "within k", c.mismatchedWithinK);
        pair("background", c.background, "facing away", c.facingAway);
        pair("outside cone", c.outsideCone, "boundary", c.boundaryPixels);
        pair("non-finite", c.nonFinite, "coverage diff", c.coverageMismatch);
        ImGui::EndTable();
    }
}

void costTab(const AccuracyState& a, const AccuracyReport& r) {
    const AccuracyCost& k = r.cost;
    if (r.live && ImGui::BeginTable("cost", 2, ImGuiTableFlags_SizingFixedFit)) {
        row("live count", format("%.1f ms", k.totalMs), "the job's wall time: tool frame + GPU count + probes");
        row("tool frame", format("%.1f ms", k.toolFrameMs), "shadow pass + shadow-factor pass, not read back");
        row("GPU count", format("%.1f ms", k.metricsMs), "compute passes over S and the cached reference");
        row("probes", format("%.1f ms", k.probeMs) + " (" + grouped(k.probedPixels) + " px)",
            "pixels mismatched far from any visible edge for the first time: probed once on the CPU");
        if (k.uploadMs > 0.0) row("upload", format("%.1f ms", k.uploadMs), "the reference to the GPU, once per light space");
        ImGui::EndTable();
        return;
    }
    if (!r.live && ImGui::BeginTable("cost", 2, ImGuiTableFlags_SizingFixedFit)) {
        row("total", format("%.1f ms", k.totalMs) + format(" (job %.2f s)", a.reportSeconds));
        row("BVH", k.bvhReused    ? "reused"
                   : k.bvhUpdated ? format("updated in %.2f ms", k.bvhUpdateMs) + " (" +
                                        grouped(k.instancesMoved) + " instances moved)"
                                  : format("%.1f ms", k.bvhBuildMs) + " (" + grouped(k.triangles) + " tris)");
        row("rays", k.referenceReused ? "reused (" + grouped(k.rays) + ")"
                                      : grouped(k.rays) + format(" in %.1f ms", k.traceMs));
        row("rays/s", k.referenceReused ? "-" : format("%.2f M", k.raysPerSecond * 1e-6) +
                                                    " on " + std::to_string(k.threads) + " threads");
        row("G-buffer", k.referenceReused ? "reused" : format("%.1f ms", k.gbufferMs));
        row("boundary", format("%.1f ms", k.boundaryMs) + format(", probes %.1f ms", k.probeMs));
        row("tool frame", format("%.1f ms", k.toolFrameMs));
        ImGui::EndTable();
    }
}

// The technique's trade-off candidates: one column per key the search varies (its last word), acne, the error it
// compares and the bleeding (soft numbers for a light with a size, else version 2's mean |S-V| and leak).
void tradeOffTable(EditorState& state, const std::vector<TuneStep>& steps, float height) {
    AccuracyState& a = state.accuracy;
    const std::size_t keys = a.searchedKeys.size();
    const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingFixedFit;
    if (ImGui::BeginTable("tradeOffSteps", int(keys) + 4, flags, ImVec2(0, height))) {
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableSetupColumn("#");
        for (std::size_t k = 0; k < keys; ++k) ImGui::TableSetupColumn(std::string(1, char('a' + k)).c_str());
        const bool soft = !steps.empty() && steps.front().soft;
        for (const char* h : {"acne", soft ? "soft |S-V|" : "|S-V|", soft ? "bleed" : "leak"}) ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        for (const TuneStep& s : steps) {
            ImGui::TableNextRow();
            if (s.bestSoFar) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, IM_COL32(40, 90, 50, 255));
            ImGui::TableNextColumn();
            ImGui::Text("%d", s.index);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("candidate %d: %s", s.index, s.phase.c_str());
            for (std::size_t k = 0; k < keys; ++k) {
                ImGui::TableNextColumn();
                if (k < s.tradeOff.size()) ImGui::Text("%.3g", s.tradeOff[k]);
            }
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", s.acnePercent);
            ImGui::TableNextColumn();
            ImGui::Text("%.4f", tradeOffError(s));
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", tradeOffBleeding(s));
        }
        if (a.steps.size() != a.stepsFollowed) {  // follow the search: a new candidate scrolls into view
            ImGui::SetScrollHereY(1.0f);
            a.stepsFollowed = a.steps.size();
        }
        ImGui::EndTable();
    }
    state.controls.recordLastItem("accuracy.tradeOffSteps");
}

void biasSearchTab(PanelContext& ctx) {
    EditorState& state = ctx.state;
    AccuracyState& a = state.accuracy;

    // What the running or newest search varies, and for which light.
    if ((a.running && a.runningTune) || a.tune) {
        std::string keys;
        for (const std::string& k : a.searchedKeys) keys += (keys.empty() ? "" : ", ") + k;
        const std::string what =
            a.searched == TuneSearch::Bias       ? "the bias (DepthBias, slope, normal offset, cull, receiver plane)"
            : a.searched == TuneSearch::TradeOff ? "filter.kind " + a.searchedTechnique + "'s trade-off: " + keys
                                                 : "the bias, then filter.kind " + a.searchedTechnique + "'s trade-off: " + keys;
        noteText("Searched " + what + ", for light " + std::to_string(a.searchedLight));
        state.controls.recordLastItem("accuracy.searched");
    }
    // The result first, so it is seen without scrolling; the path below follows the search.
    if (a.tune && a.tune->ok) {
        // The technique's chosen values (as keys of the whole preset), then the criterion's figures.
        std::string values;
        if (a.tune->tradeOffSearched)
            for (const std::string& k : a.tune->tradeOffKeys)
                values += keyOfLight(k, a.searchedLight) + " " + findSettingsField(k)->get(a.tune->closest).dump() + ", ";
        const std::string text =
            a.tune->reachedLimit
                ? "applied: " + values + "acne " + format("%.3f %%", a.tune->report.acnePercent) + " <= " +
                      format("%.1f %%", a.maxAcnePercent) + ", wrong pixels " +
                      format("%.3f %%", a.tune->report.wrongPercent) +
                      (a.searched == TuneSearch::TradeOff
                           ? ", leak " + format("%.3f %%", a.tune->report.leakPercent)
                           : ", cull " + cullModeName(a.tune->best.lights.front().shadow.cullMode))
                : "NO setting reached acne <= " + format("%.1f %%", a.maxAcnePercent) + " (least: " +
                      format("%.3f %%", a.tune->report.acnePercent) + "); stopped by " +
                      causeInfo(a.tune->blockingCause).name + ": " + causeInfo(a.tune->blockingCause).remedy +
                      ". Nothing applied.";
        ImGui::PushStyleColor(ImGuiCol_Text, a.tune->reachedLimit ? ImVec4(0.5f, 0.9f, 0.5f, 1.0f)
                                                                  : ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", text.c_str());
        ImGui::PopStyleColor();
        state.controls.recordLastItem("accuracy.result");
        if (ImGui::IsItemHovered()) {
            const ShadowMapSettings& best = a.tune->closest.lights.front().shadow;  // the tuned light, alone
            ImGui::SetTooltip("DepthBias %g, SlopeScaledDepthBias %g, normal offset %g texels\n%zu candidates in %.1f s",
                              double(best.depthBias), double(best.slopeScaledDepthBias), double(best.normalOffset),
                              a.tune->path.size(), a.tune->seconds);
        }
        for (const std::string& clamp : a.tune->startClamps) noteText("start: " + clamp);
        if (a.tune->reachedLimit) {
            if (ImGui::SmallButton("Save as preset...")) ctx.actions.openSaveAs();
            state.controls.recordLastItem("accuracy.saveAs");
            ImGui::SameLine();
        }
        ImGui::TextDisabled("%zu candidates, %.1f s", a.tune->path.size(), a.tune->seconds);
    } else if (a.steps.empty()) {
        noteText(format("Suggest: acne <= %.1f %%, then the fewest wrong pixels (bias) or the least error (a "
                        "technique's trade-off)", a.maxAcnePercent));
    }

    std::vector<TuneStep> biasSteps, tradeOffSteps;
    for (const TuneStep& s : a.steps) (s.tradeOffStep ? tradeOffSteps : biasSteps).push_back(s);
    const int tables = (biasSteps.empty() ? 0 : 1) + (tradeOffSteps.empty() ? 0 : 1);
    // Every column within the sidebar, none behind a horizontal scroll: short headers with their legend, and each
    // candidate's phase of the search on hovering its row (the newest one's above the table while it runs).
    if (!biasSteps.empty()) {
        noteText("bias = DepthBias, slope = SlopeScaledDepthBias, normal = normal offset (texels); acne, leak, wrong "
                 "in %" + std::string(a.running ? "; now: " + a.steps.back().phase : std::string()));
        state.controls.recordLastItem("accuracy.stepsLegend");
    }
    const float avail = std::max(3.0f * ImGui::GetTextLineHeightWithSpacing(), ImGui::GetContentRegionAvail().y);
    const float tableHeight = tables == 2 ? std::max(3.0f * ImGui::GetTextLineHeightWithSpacing(),
                                                     0.5f * avail - 2.0f * ImGui::GetTextLineHeightWithSpacing())
                                          : avail;
    const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingFixedFit;
    if (tradeOffSteps.empty() || !biasSteps.empty()) {  // the bias search's candidates (an empty table before any)
        if (ImGui::BeginTable("steps", 8, flags, ImVec2(0, tableHeight))) {
            ImGui::TableSetupScrollFreeze(0, 1);
            for (const char* h : {"#", "bias", "slope", "normal", "cull", "acne", "leak", "wrong"}) ImGui::TableSetupColumn(h);
            ImGui::TableHeadersRow();
            for (const TuneStep& s : biasSteps) {
                ImGui::TableNextRow();
                if (s.bestSoFar) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, IM_COL32(40, 90, 50, 255));
                ImGui::TableNextColumn();
                ImGui::Text("%d", s.index);
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("candidate %d: %s", s.index, s.phase.c_str());
                ImGui::TableNextColumn();
                ImGui::Text("%.6g", double(s.depthBias));
                ImGui::TableNextColumn();
                ImGui::Text("%.3g", double(s.slopeScaledDepthBias));
                ImGui::TableNextColumn();
                ImGui::Text("%.3g", double(s.normalOffset));
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(cullModeName(s.cullMode).c_str());
                ImGui::TableNextColumn();
                ImGui::Text("%.3f", s.acnePercent);
                ImGui::TableNextColumn();
                ImGui::Text("%.3f", s.leakPercent);
                ImGui::TableNextColumn();
                ImGui::Text("%.3f", s.wrongPercent);
            }
            // Follow the search: a new candidate scrolls into view.
            if (a.steps.size() != a.stepsFollowed && tradeOffSteps.empty()) {
                ImGui::SetScrollHereY(1.0f);
                a.stepsFollowed = a.steps.size();
            }
            ImGui::EndTable();
        }
        state.controls.recordLastItem("accuracy.steps");
    }
    if (!tradeOffSteps.empty()) {
        std::string legend;  // the key columns by letter: every column within the sidebar
        for (std::size_t k = 0; k < a.searchedKeys.size(); ++k)
            legend += std::string(1, char('a' + k)) + " = " + a.searchedKeys[k] + ", ";
        noteText(legend + "acne %, the error it compares, " +
                 (tradeOffSteps.front().soft ? "bleeding % (soft reference)" : "leak %") +
                 (a.running ? "; now: " + a.steps.back().phase : std::string()));
        state.controls.recordLastItem("accuracy.tradeOffLegend");
        tradeOffTable(state, tradeOffSteps, tableHeight);
    }
}

// Flicker: what moves, by how much, for how many frames; the figures beside the V-changed share; the overlay.
void flickerTab(PanelContext& ctx) {
    EditorState& state = ctx.state;
    AccuracyState& a = state.accuracy;
    Motion& m = a.flickerMotion;
    ImGui::BeginDisabled(a.running);
    ImGui::SetNextItemWidth(120.0f);
    if (ImGui::BeginCombo("motion", motionName(m.kind))) {
        for (const MotionInfo& info : motionKinds())
            if (ImGui::Selectable(info.name, info.kind == m.kind) && info.kind != m.kind) {
                m.kind = info.kind;
                m.step = info.typicalStep;
            }
        ImGui::EndCombo();
    }
    state.controls.recordLastItem("accuracy.flicker.motion");
    const std::string stepLabel = std::string(motionInfo(m.kind).unit) + " / frame";
    const float inner = ImGui::GetStyle().ItemInnerSpacing.x;
    sameLineIfFits(90.0f + inner + ImGui::CalcTextSize("frames").x);
    ImGui::SetNextItemWidth(90.0f);
    ImGui::InputInt("frames", &m.frames);
    m.frames = std::clamp(m.frames, 2, kMaxMotionFrames);
    state.controls.recordLastItem("accuracy.flicker.frames");
    sameLineIfFits(110.0f + inner + ImGui::CalcTextSize(stepLabel.c_str()).x);
    ImGui::SetNextItemWidth(110.0f);
    ImGui::InputDouble(stepLabel.c_str(), &m.step, 0.0, 0.0, "%.4g");
    state.controls.recordLastItem("accuracy.flicker.step");
    if (ImGui::Button("Measure flicker")) ctx.actions.measureFlicker();
    state.controls.recordLastItem("accuracy.flicker.measure");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Play the motion on light %zu and compare S at the same surface points of consecutive "
                          "frames: flicker = S flips across 0.5 while the true visibility V does not",
                          m.light);
    ImGui::EndDisabled();
    if (!a.flicker) {
        noteText("Measure flicker to see how much the shadow crawls under a sub-texel motion");
        return;
    }
    const FlickerReport& f = *a.flicker;
    if (ImGui::BeginTable("flicker", 2, ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);  // wraps (row())
        row("flicker", format("max %.3f %%, mean %.3f %%", f.maxFlickerPercent, f.meanFlickerPercent),
            "pixels whose S crosses 0.5 at the same surface point between consecutive frames while V does not");
        state.controls.recordLastItem("accuracy.flicker.figure");
        row("V changed", format("max %.3f %%, mean %.3f %%", f.maxVChangedPercent, f.meanVChangedPercent),
            "pixels whose true visibility changed: the shadow really moved (not flicker)");
        row("|dS| > 1/8", format("max %.3f %%, mean %.3f %%", f.maxVisibleDeltaPercent, f.meanVisibleDeltaPercent),
            "a visible change of S while V does not, flips included");
        row("mean |dS|", format("max %.5f, mean %.5f", f.maxMeanAbsDeltaS, f.meanMeanAbsDeltaS),
            "over pixels whose V did not change");
        row("step", format("%g ", f.motion.step) + motionInfo(f.motion.kind).unit +
                        format(" = %.3g texels", f.stepTexels) + (f.stepTexels < 1.0 ? " (sub-texel)" : ""),
            "per frame; in texels of the light's map");
        std::size_t rerendered = 0;
        for (const FlickerPair& p : f.pairs) rerendered += p.shadowViewsRendered;
        row("frames", format("%.0f (", double(f.motion.frames)) + motionName(f.motion.kind) +
                          format(" motion), %.0f shadow views re-rendered", double(rerendered)) +
                          format(", %.2f s", a.flickerSeconds));
        ImGui::EndTable();
    }
    if (a.flickerTexture && f.width > 0) {
        // The overlay at the panel's width: flickering pixels and V changes over the last frame, dimmed.
        const float w = std::max(1.0f, ImGui::GetContentRegionAvail().x);
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(a.flickerTexture.id())),
                     ImVec2(w, w * float(f.height) / float(f.width)));
        state.controls.recordLastItem("accuracy.flicker.overlay");
        for (const LegendEntry& e : flickerLegend()) {
            ImGui::ColorButton(e.name, ImVec4(e.red / 255.0f, e.green / 255.0f, e.blue / 255.0f, 1.0f),
                               ImGuiColorEditFlags_NoTooltip, ImVec2(10, 10));
            ImGui::SameLine();
            ImGui::TextUnformatted(e.name);
        }
    }
}

}  // namespace

void drawAccuracyPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    AccuracyState& a = state.accuracy;

    ImGui::BeginDisabled(a.running);
    if (ImGui::Button("Measure")) ctx.actions.measureAccuracy();
    state.controls.recordLastItem("accuracy.measure");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Measure this view against the exact reference (shadow rays)");
    ImGui::SameLine();
    bool startedSearch = false;
    // The button says what it will search for the chosen technique (the search combo beside it: tune's --search).
    const FilterKind kind = state.settings.filter.kind;
    const TuneSearch willSearch = resolveTuneSearch(TuneScope{a.search, true}, kind);
    const std::string technique = filterTechnique(kind).name;
    const std::string suggestLabel = willSearch == TuneSearch::Bias       ? "Suggest bias"
                                     : willSearch == TuneSearch::TradeOff ? "Suggest " + technique
                                                                          : "Suggest bias + " + technique;
    if (ImGui::Button((suggestLabel + "###suggest").c_str())) {
        ctx.actions.suggestBias();
        startedSearch = true;
    }
    state.controls.recordLastItem("accuracy.suggest");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        std::string keys;
        for (const std::string& k : tradeOffKeysOf(TuneScope{a.search, true}, kind)) keys += (keys.empty() ? "" : ", ") + k;
        const std::string bias = "DepthBias, slope, normal offset (and cull mode when culled casters cause wrong pixels) "
                                 "for acne <= " + format("%.1f %%", a.maxAcnePercent) + " with the fewest wrong pixels";
        const std::string tradeOff = "filter.kind " + technique + "'s trade-off (" + keys + ") for acne <= " +
                                     format("%.1f %%", a.maxAcnePercent) +
                                     ", then the least error (soft numbers for a light with a size)";
        const std::string what = willSearch == TuneSearch::Bias       ? bias
                                 : willSearch == TuneSearch::TradeOff ? tradeOff
                                                                      : bias + ", then " + tradeOff;
        ImGui::SetTooltip("Search %s, and apply the result to the selected light", what.c_str());
    }
    // What Suggest searches, as `shadowlab tune --search`: auto = the technique's trade-off when it declares one.
    sameLineIfFits(100.0f);
    ImGui::SetNextItemWidth(100.0f);
    if (ImGui::BeginCombo("##search", tuneSearchName(a.search), ImGuiComboFlags_HeightLargest)) {
        for (TuneSearch option : {TuneSearch::Auto, TuneSearch::Bias, TuneSearch::TradeOff, TuneSearch::Both}) {
            const bool selected = option == a.search;
            if (ImGui::Selectable(tuneSearchName(option), selected)) a.search = option;
            state.controls.recordLastItem(std::string("accuracy.search=") + tuneSearchName(option));
        }
        ImGui::EndCombo();
    }
    state.controls.recordLastItem("accuracy.search");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("What Suggest searches (tune --search): auto = the technique's own trade-off when it declares "
                          "one (vsm, evsm, msm, pcss), else the bias; bias; technique = its trade-off; both = the bias, "
                          "then the trade-off from the bias found");
    // The soft reference's rays per pixel (reference.softRays): read only for a light of size > 0.
    int softRays = state.settings.reference.softRays;
    ImGui::SetNextItemWidth(110.0f);
    if (ImGui::InputInt("soft rays", &softRays, 0, 0, ImGuiInputTextFlags_EnterReturnsTrue))
        state.edit("reference.softRays", softRays);
    state.controls.recordLastItem(controlName("reference.softRays"));
    fieldHelp(state, "reference.softRays");
    showFieldError(state, "reference.softRays");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!a.running);
    if (ImGui::Button("Cancel")) ctx.actions.cancelAccuracy();
    state.controls.recordLastItem("accuracy.cancel");
    ImGui::EndDisabled();
    if (ImGui::SmallButton("Cost vs accuracy...")) state.sweep.open = !state.sweep.open;
    state.controls.recordLastItem("accuracy.costVsAccuracy");

    // Progress, or what the newest job did.
    char overlay[160];
    if (a.running)
        std::snprintf(overlay, sizeof overlay, "%s %s (%.0f %%)",
                      a.runningTune ? (a.searched == TuneSearch::Bias ? "bias search:" : "search:")
                      : a.runningFlicker ? "flicker:" : "measure:",
                      a.stage.c_str(), double(a.progress) * 100.0);
    else if (!a.error.empty())
        std::snprintf(overlay, sizeof overlay, "%s", a.stage.c_str());
    else if (a.report && a.report->live)
        std::snprintf(overlay, sizeof overlay, "live count %dx%d in %.0f ms", a.report->width, a.report->height,
                      a.reportSeconds * 1e3);
    else if (a.report)
        std::snprintf(overlay, sizeof overlay, "%s %dx%d in %.2f s", a.reportFromSearch ? (a.searched == TuneSearch::Bias ? "bias search at" : "search at") : "measured",
                      a.report->width, a.report->height, a.reportSeconds);
    else
        std::snprintf(overlay, sizeof overlay, "not measured yet");
    // Beside the buttons where there is room, else on its own line.
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < 220.0f) ImGui::NewLine();
    ImGui::PushStyleColor(ImGuiCol_PlotHistogram, ImVec4(0.22f, 0.42f, 0.70f, 1.0f));
    ImGui::ProgressBar(a.running ? a.progress : (a.report ? 1.0f : 0.0f), ImVec2(-1, 0), overlay);
    ImGui::PopStyleColor();
    state.controls.recordLastItem("accuracy.progress");
    ImGui::Checkbox("Auto (live while editing, in full once still)", &a.autoMeasure);
    state.controls.recordLastItem("accuracy.auto");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("After a Measure, every edit of bias, filter or map is re-counted on the GPU against the "
                          "cached reference (live, also while a slider moves); once the view has been still for "
                          "%.1f s it is measured in full (causes, overlay). A camera or light move needs new rays: "
                          "then only the full measure runs.",
                          AccuracyState::kAutoDelaySeconds);
    if (a.report && a.report->live && a.stale.empty()) {
        char live[160];
        std::snprintf(live, sizeof live, "live: counted on the GPU in %.1f ms (%ld counts); causes and overlay once still",
                      a.report->cost.totalMs, a.liveMeasurements);
        noteText(live);
        state.controls.recordLastItem("accuracy.live");
    }

    // Which light the numbers describe: the selected light when measured, measured alone (never light 0 silently).
    if (a.reportKey) {
        const std::size_t count = a.reportKey->settings.lights.size();
        noteText("Numbers of light " + std::to_string(a.reportKey->light) + " (" +
                 lightTypeText(a.reportKey->settings, a.reportKey->light) + ")" +
                 (count > 1 ? ", one of " + std::to_string(count) + " lights, measured alone (select another light and Measure for its numbers)" : ""));
        state.controls.recordLastItem("accuracy.light");
    }
    if (!a.error.empty() && !a.running) {
        errorText(a.error);
        state.controls.recordLastItem("accuracy.error");
    }
    if (!a.stale.empty()) {
        warningText("Stale: " + a.stale);
        state.controls.recordLastItem("accuracy.stale");
    }

    if (!ImGui::BeginTabBar("accuracyTabs")) return;
    auto tab = [&](const char* label, const char* control, ImGuiTabItemFlags flags = 0) {
        const bool open = ImGui::BeginTabItem(label, nullptr, flags);
        state.controls.recordLastItem(control);
        return open;
    };
    if (tab("Numbers", "accuracy.tab.numbers")) {
        if (a.report)
            numbersTab(state, *a.report);
        else
            noteText("Measure, or turn on Auto, to see how wrong the shadows are");
        ImGui::EndTabItem();
    }
    if (tab("Causes", "accuracy.tab.causes")) {
        if (a.report) causesTab(state, *a.report);
        ImGui::EndTabItem();
    }
    if (tab("Counts", "accuracy.tab.counts")) {
        if (a.report) countsTab(*a.report);
        ImGui::EndTabItem();
    }
    if (tab("Cost", "accuracy.tab.cost")) {
        if (a.report) costTab(a, *a.report);
        ImGui::EndTabItem();
    }
    // "Tune" as `shadowlab tune`: with Flicker the six tabs fit the sidebar at 1280x720.
    if (tab("Tune", "accuracy.tab.search", startedSearch ? ImGuiTabItemFlags_SetSelected : 0)) {
        biasSearchTab(ctx);
        ImGui::EndTabItem();
    }
    if (tab("Flicker", "accuracy.tab.flicker")) {
        flickerTab(ctx);
        ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
}

}  // namespace shadowlab::editor
