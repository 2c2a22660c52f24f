// Shadow map viewer: the depth map as a picture with contrast / linearization, wheel zoom about the cursor, drag
// to pan, a texel grid when zoomed in, and the texel and stored depth under the cursor. Under a moments technique
// it shows either the depth or one stored moment (after the blur), the line under the choice naming the light, the
// view and the range shown.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "shading/filters/filter_technique.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace shadowlab::editor {

namespace {

void contrastControls(MapViewerState& v, bool spot, EditorState& state) {
    int contrast = int(v.options.contrast);
    ImGui::TextUnformatted("contrast");
    ImGui::SameLine();
    ImGui::RadioButton("auto", &contrast, int(DepthContrast::Auto));
    state.controls.recordLastItem("viewer.auto");
    ImGui::SameLine();
    ImGui::RadioButton("full", &contrast, int(DepthContrast::Full));
    state.controls.recordLastItem("viewer.full");
    ImGui::SameLine();
    ImGui::RadioButton("manual", &contrast, int(DepthContrast::Manual));
    state.controls.recordLastItem("viewer.manual");
    v.options.contrast = DepthContrast(contrast);
    if (spot) {
        ImGui::SameLine();
        ImGui::Checkbox("linear", &v.options.linearize);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show distance from the light instead of stored depth");
    } else {
        v.options.linearize = false;  // orthographic depth is already linear
    }
    if (v.options.contrast == DepthContrast::Manual) {
        ImGui::SetNextItemWidth(-1);
        ImGui::DragFloatRange2("##range", &v.options.manualMin, &v.options.manualMax, 0.001f, 0.0f, 1.0f, "min %.4f",
                               "max %.4f", ImGuiSliderFlags_AlwaysClamp);
        if (v.options.manualMax <= v.options.manualMin) v.options.manualMax = std::min(1.0f, v.options.manualMin + 1e-4f);
    }
}

// The probe's taps over the map picture: each compared texel outlined green (lit) or red (shadowed), orange when
// rounding decides, and a yellow cross at the lookup. Texels smaller than a few pixels get a minimum-size marker.
void drawProbeTaps(const PixelProbeReport& r, const UvRect& visible, ImVec2 pos, int size, EditorState& state) {
    if (r.resolution < 1) return;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(pos, ImVec2(pos.x + float(size), pos.y + float(size)), true);
    const double res = double(r.resolution);
    auto at = [&](double u, double v) {
        const glm::dvec2 p = uvToView(visible, {u, v}, size, size);
        return ImVec2(pos.x + float(p.x), pos.y + float(p.y));
    };
    for (const ProbeTap& tap : r.taps)
        for (const ProbeTexel& t : tap.texels) {
            if (t.border) continue;
            ImVec2 a = at(t.texel.x / res, (t.texel.y + 1) / res), b = at((t.texel.x + 1) / res, t.texel.y / res);
            if (b.x - a.x < 3.0f) {
                const ImVec2 c((a.x + b.x) * 0.5f, (a.y + b.y) * 0.5f);
                a = ImVec2(c.x - 1.5f, c.y - 1.5f), b = ImVec2(c.x + 1.5f, c.y + 1.5f);
            }
            const ImU32 colour = t.uncertain ? IM_COL32(255, 170, 0, 255)
                                 : t.lit     ? IM_COL32(60, 220, 80, 255)
                                             : IM_COL32(240, 50, 50, 255);
            draw->AddRect(a, b, colour, 0.0f, 0, 1.5f);
        }
    const ImVec2 c = at(r.lightTexture.x, r.lightTexture.y);
    draw->AddLine(ImVec2(c.x - 6, c.y), ImVec2(c.x + 6, c.y), IM_COL32(255, 230, 0, 255), 1.5f);
    draw->AddLine(ImVec2(c.x, c.y - 6), ImVec2(c.x, c.y + 6), IM_COL32(255, 230, 0, 255), 1.5f);
    draw->PopClipRect();
    state.controls.record("viewer.probeLookup", ControlRect{c.x - 6, c.y - 6, 12, 12});
}

// The views of the frame that have a map: "light 0", "light 2 +X", "light 0 cascade:1"... The choice is kept as
// (light, kind, index).
void viewPicker(EditorState& state) {
    MapViewerState& v = state.viewer;
    const ShadowViewStats* shown = state.shownView();
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##view", shown ? shown->name.c_str() : "no view")) {
        for (const ShadowViewStats& view : state.stats.views) {
            if (!view.hasView) continue;
            const bool selected = &view == shown;
            if (view.kind == ShadowViewKind::Cascade) cascadeSwatch(view.index);  // the colour of its frustum and tint
            if (ImGui::Selectable(view.name.c_str(), selected)) {
                v.light = view.light;
                v.kind = view.kind;
                v.index = view.index;
            }
            state.controls.recordLastItem("viewer.view=" + view.name);
        }
        ImGui::EndCombo();
    }
    state.controls.recordLastItem("viewer.view");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Which shadow view to show: a light's map, one cube face of a point light or one cascade");
}

// What the picture shows: the depth, or (a moments technique) one of its stored moments.
void channelChoice(MapViewerState& v, const FilterSettings& filter, EditorState& state) {
    const FilterTechnique& technique = filterTechnique(filter.kind);
    if (!technique.moments) {
        v.options.channel = 0;
        return;
    }
    const int channels = technique.moments->channels;
    v.options.channel = std::min(v.options.channel, channels);
    const auto name = [](int channel) { return channel == 0 ? std::string("depth") : "moment " + std::to_string(channel); };
    ImGui::TextUnformatted("show");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##channel", name(v.options.channel).c_str())) {
        for (int c = 0; c <= channels; ++c) {
            if (ImGui::Selectable(name(c).c_str(), c == v.options.channel)) v.options.channel = c;
            state.controls.recordLastItem("viewer.channel=" + name(c));
        }
        ImGui::EndCombo();
    }
    state.controls.recordLastItem("viewer.channel");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The view's depth map, or one of the %d moments %s stores (after the blur; "
                          "docs/techniques.md says what each holds)",
                          channels, technique.name);
}

// "light 0 cascade:1: moment 2 of vsm (32-bit, blur 5 texels), black 0.012 .. white 0.98": which light and view,
// what is shown and the range stretched to black..white.
std::string shownLabel(const ShadowViewStats& view, const MapViewerState& v, const FilterSettings& filter) {
    char text[256];
    if (v.options.channel == 0) {
        std::snprintf(text, sizeof text, "%s: depth, black %.4g .. white %.4g", view.name.c_str(), double(v.shown.min),
                      double(v.shown.max));
    } else {
        std::snprintf(text, sizeof text, "%s: moment %d of %s (%d-bit, blur %g %s), black %.4g .. white %.4g",
                      view.name.c_str(), v.options.channel, filterTechnique(filter.kind).name, filter.momentBits,
                      double(filter.blurWidth), filter.blurUnit == BlurUnit::World ? "world units" : "texels",
                      double(v.shown.min), double(v.shown.max));
    }
    return text;
}

}  // namespace

void drawShadowMapViewerPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    MapViewerState& v = state.viewer;
    viewPicker(state);
    const ShadowViewStats* shown = state.shownView();
    if (!shown) {
        ImGui::TextDisabled(state.haveStats ? "no light casts a shadow: no map to show" : "no frame rendered yet");
        return;
    }
    if (shown->kind == ShadowViewKind::Cascade) {
        cascadeSwatch(shown->index);
        char slice[128];
        std::snprintf(slice, sizeof slice, "cascade %d: depths %.4g .. %.4g in front of the camera", shown->index,
                      shown->slice.nearDepth, shown->slice.farDepth);
        noteText(slice);
        state.controls.recordLastItem("viewer.cascadeSlice");
    }
    const FilterSettings& filter = state.settings.filter;
    channelChoice(v, filter, state);
    v.shownLabel.clear();
    if (filterTechnique(filter.kind).moments) {
        v.shownLabel = shownLabel(*shown, v, filter);
        noteText(v.shownLabel);
        state.controls.recordLastItem("viewer.shownLabel");
    }
    const bool spot = shown->space.perspective && v.options.channel == 0;
    contrastControls(v, spot, state);
    ImGui::Checkbox("texel grid", &v.options.texelGrid);
    ImGui::SameLine();
    const double zoom = v.zoomPan.zoom();
    ImGui::Text(zoom >= 10.0 ? "zoom %.0fx" : "zoom %.2gx", zoom);
    ImGui::SameLine();
    if (ImGui::SmallButton("fit")) v.zoomPan.reset();
    state.controls.recordLastItem("viewer.fit");
    // The probe looks up the frame's first view (see PixelProbeReport): its taps belong on that map only.
    const bool firstView = &*std::find_if(state.stats.views.begin(), state.stats.views.end(),
                                          [](const ShadowViewStats& view) { return view.hasView; }) == shown;
    const PixelProbeReport* probe =
        firstView && state.probe.report && state.probe.report->ok ? &*state.probe.report : nullptr;
    bool focusProbe = false;
    if (probe) {
        ImGui::SameLine();
        focusProbe = ImGui::SmallButton("zoom to probe");
        state.controls.recordLastItem("viewer.zoomToProbe");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Centre on the probed pixel's texel, its taps outlined: green lit, red shadowed, orange "
                              "decided by rounding; the yellow cross is the lookup");
    }

    const ImVec2 avail = ImGui::GetContentRegionAvail();
    // Two lines under the picture for its info (wrapped in a narrow sidebar).
    const float side =
        std::floor(std::max(0.0f, std::min(avail.x, avail.y - 2.0f * ImGui::GetTextLineHeightWithSpacing())));
    if (side < 16.0f) return;
    const int size = int(side);
    v.width = v.height = size;
    const int resolution = shown->resolution;

    const ImVec2 pos = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##map", ImVec2(side, side));
    state.controls.recordLastItem("viewer.image");
    if (v.texture != 0 && v.textureWidth == size) {
        ImGui::GetWindowDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(v.texture)), pos,
                                             ImVec2(pos.x + side, pos.y + side), ImVec2(0, 1), ImVec2(1, 0));
    } else {
        ImGui::GetWindowDrawList()->AddRect(pos, ImVec2(pos.x + side, pos.y + side), IM_COL32(90, 90, 90, 255));
    }

    const ImGuiIO& io = ImGui::GetIO();
    const double mx = io.MousePos.x - pos.x, my = io.MousePos.y - pos.y;
    if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f)
        v.zoomPan.zoomAt(mx, my, std::pow(1.25, double(io.MouseWheel)), size, size, resolution);
    if (ImGui::IsItemActive() && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f))
        v.zoomPan.pan(io.MouseDelta.x, io.MouseDelta.y, size, size);
    if (focusProbe)  // about 24 texels across the picture: every tap of a 9x9 kernel shows
        v.zoomPan.focus(glm::dvec2(probe->lightTexture), double(resolution) / 24.0, size, size, resolution);
    v.options.visible = v.zoomPan.visibleRect(size, size);
    if (probe && v.texture != 0 && v.textureWidth == size) drawProbeTaps(*probe, v.options.visible, pos, size, state);
    if (ImGui::IsItemHovered()) v.hoverTexel = texelAtView(v.options.visible, mx, my, size, size, resolution);

    if (!v.error.empty()) {
        errorText(v.error);
    } else if (v.hoverTexel && v.options.channel > 0 && v.hoverMoments) {
        ImGui::Text("texel (%d, %d): moments %.5g, %.5g, %.5g, %.5g", v.hoverTexel->x, v.hoverTexel->y,
                    double(v.hoverMoments->x), double(v.hoverMoments->y), double(v.hoverMoments->z),
                    double(v.hoverMoments->w));
    } else if (v.hoverTexel && v.hoverDepth) {
        ImGui::Text("texel (%d, %d): depth %.6f%s", v.hoverTexel->x, v.hoverTexel->y, double(*v.hoverDepth),
                    *v.hoverDepth >= 1.0f ? " (no caster)" : "");
    } else {
        char info[160];
        std::snprintf(info, sizeof info, "%d² | black %.4g .. white %.4g%s | wheel: zoom, drag: pan", resolution,
                      double(v.shown.min), double(v.shown.max), v.gridShown ? " | grid" : "");
        noteText(info);
    }
    state.controls.recordLastItem("viewer.info");
}

}  // namespace shadowlab::editor
