// The editor's UI for one frame: shortcuts, the viewport (behind everything, filling what the panels leave), the
// panels from the registry, the unsaved-changes and Save As dialogs.
#include "editor/editor.h"
#include "editor/editor_keys.h"
#include "editor/field_widgets.h"
#include "editor/message_log.h"
#include "editor/panels/panel_registry.h"
#include "frame/surface_pick.h"
#include "settings/settings_fields.h"

#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace shadowlab::editor {

namespace {

// Opens the modal `title` once `open` is set (then clears it) and begins it centred in the window; false while it is
// not showing.
bool beginCentredModal(const char* title, bool& open) {
    if (open) {
        ImGui::OpenPopup(title);
        open = false;
    }
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    return ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

constexpr float kStatusHeight = 26.0f;
// The view combo's editor-only choices (the accuracy overlays); the second is its longest label.
constexpr const char* kOverlay = "accuracy overlay";
constexpr const char* kCauseOverlay = "accuracy overlay by cause";
constexpr const char* kSoftOverlay = "soft overlay";
constexpr std::pair<const char*, OverlayKind> kOverlayChoices[] = {
    {kOverlay, OverlayKind::Error}, {kCauseOverlay, OverlayKind::Cause}, {kSoftOverlay, OverlayKind::Soft}};

}  // namespace

void Editor::buildUi() {
    state_.controls = ControlRects{};
    state_.viewer.width = state_.viewer.height = 0;  // set again by the viewer panel when it is visible
    state_.viewer.hoverTexel.reset();
    handleShortcuts();
    closePopupOnEscape();
    drawViewport();
    drawPanels();
    drawUnsavedChangesDialog();
    drawSaveAsDialog();
    drawRestoreDialog();
    keepSessionBeforeRiskyChange();  // after this frame's edits, before the next frame renders them
}

void Editor::handleShortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsKeyPressed(keys::kF12, false)) {
        if (io.KeyCtrl)
            windowScreenshotPath_ = windowScreenshotPath(state_.screenshotDir);
        else
            requestScreenshot(state_.screenshotWithShadowMap);
    }
    if (io.KeyCtrl && ImGui::IsKeyPressed(keys::kS, false)) savePreset();
    if (io.KeyCtrl && ImGui::IsKeyPressed(keys::kQ, false)) requestQuit();
    if (!io.WantTextInput && !io.KeyCtrl && ImGui::IsKeyPressed(keys::kF, false)) frameScene();
}

// Escape closes an open combo or popup (ImGui does so only with keyboard navigation on, which the editor leaves off).
// Modal dialogs keep their own Escape handling (Cancel).
void Editor::closePopupOnEscape() {
    ImGuiContext& g = *ImGui::GetCurrentContext();
    if (g.OpenPopupStack.empty() || !ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) return;
    int level = g.OpenPopupStack.Size;
    while (level > 0) {
        const ImGuiWindow* window = g.OpenPopupStack[level - 1].Window;
        if (window && (window->Flags & ImGuiWindowFlags_Modal)) break;
        --level;
    }
    if (level < g.OpenPopupStack.Size) ImGui::ClosePopupToLevel(level, true);
}

ImVec4 Editor::viewportWindowRect() const {
    // Between the two sidebars, the window's whole height.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float left = sidebarWidth(Sidebar::Left, display);
    const float right = display.x - sidebarWidth(Sidebar::Right, display);
    if (right - left < 160.0f || display.y < 120.0f) return ImVec4(0, 0, display.x, display.y);
    return ImVec4(left, 0.0f, right - left, display.y);
}

void Editor::drawViewport() {
    const ImVec4 rect = viewportWindowRect();
    ImGui::SetNextWindowPos(ImVec2(rect.x, rect.y));
    ImGui::SetNextWindowSize(ImVec2(rect.z, rect.w));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                   ImGuiWindowFlags_NoScrollWithMouse;
    ImGui::Begin("Viewport", nullptr, flags);
    ImGui::PopStyleVar(3);

    // Toolbar: what the view shows, the light's frustum, screenshots, framing. It flows onto a second row when the
    // view is narrow (1280x720), so no control is cut at the view's edge.
    const ImGuiStyle& style = ImGui::GetStyle();
    const auto buttonWidth = [&](const char* label) { return ImGui::CalcTextSize(label).x + 2.0f * style.FramePadding.x; };
    const auto checkboxWidth = [&](const char* label) {
        return ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
    };
    const auto flow = [&](float itemWidth) {
        ImGui::SameLine();
        if (ImGui::GetContentRegionAvail().x < itemWidth + 8.0f) {
            ImGui::NewLine();
            ImGui::SetCursorPosX(8.0f);
        }
    };
    ImGui::SetCursorPos(ImVec2(8, 6));
    // Wide enough for its longest choice ("accuracy overlay by cause") and the arrow.
    ImGui::SetNextItemWidth(ImGui::CalcTextSize(kCauseOverlay).x + 2.0f * style.FramePadding.x +
                            ImGui::GetFrameHeight());
    viewModeCombo();
    flow(buttonWidth(state_.ab.active ? "A/B ..." : "A/B"));
    abToolbar();  // next to what the view shows: it splits the view
    flow(checkboxWidth("light frustum"));
    ImGui::Checkbox("light frustum", &state_.showLightFrustum);
    state_.controls.recordLastItem("viewport.frustum");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The selected light's volume over the view; a cascaded light's cascades each in the colour "
                          "of the cascades view");
    const bool cascaded = std::any_of(state_.stats.views.begin(), state_.stats.views.end(), [](const ShadowViewStats& v) {
        return v.hasView && v.kind == ShadowViewKind::Cascade;
    });
    if (cascaded || state_.frozenCascadeCamera) {  // only where there are cascades to freeze (or to let go)
        flow(checkboxWidth("freeze cascades"));
        freezeCascadesToggle();
    }
    flow(buttonWidth("Frame (F)"));
    if (ImGui::Button("Frame (F)")) frameScene();
    state_.controls.recordLastItem("viewport.frame");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Frame the scene (F). In the view: left drag orbits, middle or Shift+left drag pans, the "
                          "wheel zooms, Alt+click sets the orbit's pivot on the surface clicked. Right drag flies: "
                          "the mouse looks around, W A S D travel, Q / E go down / up, Shift is 4x faster, the wheel "
                          "sets the speed");
    flow(buttonWidth("Reset view"));
    if (ImGui::Button("Reset view")) resetCameraFromSettings();
    state_.controls.recordLastItem("viewport.resetView");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Back to the preset's camera (the view it was tuned from; auto-framed when it has none)");
    flow(buttonWidth("Screenshot (F12)"));
    if (ImGui::Button("Screenshot (F12)")) requestScreenshot(state_.screenshotWithShadowMap);
    state_.controls.recordLastItem("viewport.screenshot");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Writes the viewport as PNG into %s/ (Ctrl+F12: the whole window)",
                          state_.screenshotDir.c_str());
    flow(checkboxWidth("+ shadow map"));
    ImGui::Checkbox("+ shadow map", &state_.screenshotWithShadowMap);
    state_.controls.recordLastItem("viewport.screenshotWithMap");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Screenshots also write the shadow map as float EXR and PNG");
    // How to move the camera, where there is room for it (else on the Frame button's tooltip).
    const char* help = "drag: orbit | middle / Shift+drag: pan | wheel: zoom | Alt+click: pivot | right drag + WASD: fly";
    const float helpWidth = ImGui::CalcTextSize(help).x;
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x > helpWidth + 12.0f) {
        ImGui::SetCursorPosX(rect.z - helpWidth - 10.0f);
        ImGui::TextDisabled("%s", help);
    } else {
        ImGui::NewLine();
    }
    const float toolbarHeight = ImGui::GetCursorPosY();

    // The image: the renderer draws at exactly this size.
    const ImVec2 origin = ImGui::GetWindowPos();
    const ImVec2 imagePos(origin.x, origin.y + toolbarHeight);
    const ImVec2 imageSize(rect.z, std::max(0.0f, rect.w - toolbarHeight - kStatusHeight));
    viewportRect_ = ImVec4(imagePos.x, imagePos.y, std::floor(imageSize.x), std::floor(imageSize.y));
    abDividerInput(imagePos, imageSize);
    ImGui::SetCursorScreenPos(imagePos);
    if (imageSize.x >= 1.0f && imageSize.y >= 1.0f) {
        ImGui::InvisibleButton("##view", imageSize,
                               ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonMiddle |
                                   ImGuiButtonFlags_MouseButtonRight);
        state_.controls.recordLastItem("viewport.image");
        ImDrawList* draw = ImGui::GetWindowDrawList();
        const AccuracyState& a = state_.accuracy;
        const ImVec2 imageEnd(imagePos.x + imageSize.x, imagePos.y + imageSize.y);
        if (a.overlayShown()) {
            // The overlay's row 0 is the view's top, and so is its texture's row 0.
            draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(a.overlayTexture.id())), imagePos,
                           imageEnd, ImVec2(0, 0), ImVec2(1, 1));
            drawOverlayNotes(imagePos, imageSize);
        } else if (target_.width() > 0 && state_.haveStats) {
            if (!drawAbSplit(imagePos, imageSize))
                draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(target_.colorTexture())),
                               imagePos, imageEnd, ImVec2(0, 1), ImVec2(1, 0));
            if (a.showOverlay) drawOverlayNotes(imagePos, imageSize);
            drawCascadeLegend(imagePos, imageSize);
        } else {
            draw->AddText(ImVec2(imagePos.x + 12, imagePos.y + 12), IM_COL32(200, 200, 200, 255),
                          state_.loading ? "loading the scene..." : "no frame yet");
        }
        drawProbeMarker(imagePos);
        drawProfileLine(imagePos);
        probeViewportInput(imagePos);
        viewportCameraInput(imagePos, imageSize);
        pickPivot(imagePos);
    }
    drawStatusBar();
    ImGui::End();
}

void Editor::viewportCameraInput(ImVec2 pos, ImVec2 size) {
    if (!orbit_) return;
    const ImGuiIO& io = ImGui::GetIO();
    const bool moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
    const auto inside = [&](ImVec2 p) {
        return p.x >= pos.x && p.y >= pos.y && p.x < pos.x + size.x && p.y < pos.y + size.y;
    };
    if (!ImGui::IsItemActive()) {
        cameraDragLive_ = cameraDragRefused_ = false;
    } else if (moved && !cameraDragLive_ && !cameraDragRefused_) {
        // A click on the toolbar that the window system delivered before the cursor's move reaches ImGui as a
        // press on the view whose first move lands outside it: that is no drag (it used to orbit by the whole move).
        const int button = io.MouseDown[2] ? 2 : io.MouseDown[1] ? 1 : 0;
        if (inside(io.MouseClickedPos[button]) && inside(io.MousePos))
            cameraDragLive_ = true;
        else
            cameraDragRefused_ = true;
    }
    if (cameraDragLive_ && moved) {
        if (io.MouseDown[1])
            orbit_->look(io.MouseDelta.x, io.MouseDelta.y);  // fly mode: turn around the eye
        else if (io.MouseDown[2] || (io.MouseDown[0] && io.KeyShift))
            orbit_->pan(io.MouseDelta.x, io.MouseDelta.y, int(size.y));
        else if (io.MouseDown[0] && !io.KeyCtrl)  // Ctrl+drag draws the depth profile's line
            orbit_->orbit(io.MouseDelta.x, io.MouseDelta.y);
    }
    flyInput();
    if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
        if (io.MouseDown[1]) {  // while flying the wheel sets the speed
            state_.flySpeedFactor = std::clamp(state_.flySpeedFactor * std::pow(1.25, double(io.MouseWheel)),
                                               1.0 / 64.0, 64.0);
            char text[96];
            std::snprintf(text, sizeof text, "fly speed: %.3g world units a second (x%.3g; Shift: 4x)",
                          orbit_->flySpeed() * state_.flySpeedFactor, state_.flySpeedFactor);
            state_.say(text);
        } else {
            orbit_->zoom(io.MouseWheel);
        }
    }
}

void Editor::flyInput() {
    const ImGuiIO& io = ImGui::GetIO();
    // The view holds the right button: flying. Travel follows the editor's clock, not the frame count.
    const bool flying = ImGui::IsItemActive() && io.MouseDown[1] && !io.WantTextInput;
    const auto axis = [&](int plus, int minus) { return double(io.KeysDown[plus]) - double(io.KeysDown[minus]); };
    const glm::dvec3 axes(axis(keys::kD, keys::kA), axis(keys::kE, keys::kQ), axis(keys::kW, keys::kS));
    flyMoving_ = flying && axes != glm::dvec3(0.0);
    if (!flying) {
        flyClock_.reset();
        return;
    }
    const double t = now();
    // A stalled frame does not throw the eye across the scene: at most a quarter second of travel at once.
    const double seconds = flyClock_ ? std::clamp(t - *flyClock_, 0.0, 0.25) : 0.0;
    flyClock_ = t;
    if (flyMoving_) orbit_->fly(axes, seconds, state_.flySpeedFactor * (io.KeyShift ? 4.0 : 1.0));
}

void Editor::pickPivot(ImVec2 imagePos) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool altClick = ImGui::IsItemDeactivated() && io.MouseReleased[0] && io.KeyAlt &&
                          io.MouseDragMaxDistanceSqr[0] < 9.0f;
    if (!altClick || !orbit_ || !state_.haveStats) return;
    const int x = int(std::floor(io.MousePos.x - imagePos.x)), y = int(std::floor(io.MousePos.y - imagePos.y));
    const std::optional<glm::dvec3> point = pickSurface(target_, state_.stats, x, y);
    if (!point) {
        state_.say("pivot: no surface under the cursor (pixel " + std::to_string(x) + ", " + std::to_string(y) + ")");
        return;
    }
    orbit_->setPivot(*point);
    char text[160];
    std::snprintf(text, sizeof text, "pivot: orbits now turn around (%.4g, %.4g, %.4g), the surface at pixel (%d, %d)",
                  point->x, point->y, point->z, x, y);
    state_.say(text);
}

void Editor::freezeCascadesToggle() {
    bool frozen = state_.frozenCascadeCamera.has_value();
    if (ImGui::Checkbox("freeze cascades", &frozen) && orbit_) {
        if (frozen) {
            const double aspect = viewportRect_.w > 0 ? double(viewportRect_.z) / double(viewportRect_.w) : 1.0;
            state_.frozenCascadeCamera = FitCamera{orbit_->toCamera(), aspect};
            state_.say("cascades frozen: they stay fitted to the camera as it is now; move the view to look at them "
                       "(the light frustum shows each cascade's box and its slice of the frozen camera's frustum)");
        } else {
            state_.frozenCascadeCamera.reset();
            state_.say("cascades follow the view's camera again");
        }
    }
    state_.controls.recordLastItem("viewport.freezeCascades");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Keep the cascades fitted to the camera as it is now while the view moves: fly out and see "
                          "each cascade's box and the slice of the frozen camera's frustum it covers (light frustum "
                          "on). A view setting, never saved; the Probe and Accuracy fit to the view's camera");
}

void Editor::viewModeCombo() {
    // lit / shadow / light-depth are the renderer's view setting (saved in presets); the accuracy overlay is the
    // editor's own view of the newest measurement and never a setting.
    AccuracyState& a = state_.accuracy;
    const SettingsField* field = findSettingsField("view");
    const std::string current = field->get(state_.settings).get<std::string>();
    const char* shown = current.c_str();
    for (const auto& [label, kind] : kOverlayChoices)
        if (a.showOverlay && a.overlayKind == kind) shown = label;
    if (ImGui::BeginCombo("##view", shown)) {
        for (const std::string& choice : field->choices) {
            const bool selected = !a.showOverlay && choice == current;
            if (ImGui::Selectable(choice.c_str(), selected)) {
                a.showOverlay = false;
                if (choice != current) state_.edit("view", choice);
            }
            state_.controls.recordLastItem("view=" + choice);
        }
        for (const auto& [label, kind] : kOverlayChoices) {
            if (ImGui::Selectable(label, a.showOverlay && a.overlayKind == kind)) {
                a.showOverlay = true;
                a.overlayKind = kind;
                if (a.report) uploadAccuracyOverlay();
            }
            state_.controls.recordLastItem(std::string("view=") + label);
        }
        ImGui::EndCombo();
    }
    state_.controls.recordLastItem("view");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("What the viewport shows: the lit scene, the shadow factor, the light's depth, the cascade "
                          "holding each pixel, the map's texels per screen pixel, or the accuracy overlay of the newest "
                          "measurement (red acne, blue leak, yellow true boundary; or each wrong pixel coloured by its "
                          "cause; or, for a light with a size, cyan light bleeding and orange over-darkening against "
                          "the soft reference)");
    showFieldError(state_, "view");
}

void Editor::drawCascadeLegend(ImVec2 imagePos, ImVec2 imageSize) {
    int count = 0;
    for (const ShadowViewStats& v : state_.stats.views)
        if (v.hasView && v.kind == ShadowViewKind::Cascade) count = std::max(count, v.index + 1);
    const bool shown = state_.settings.view == ViewMode::Cascades || state_.showLightFrustum;
    if (count == 0 || !(shown || state_.frozenCascadeCamera)) return;
    const char* title = state_.frozenCascadeCamera ? "cascades (frozen)" : "cascades";
    const float pad = 6.0f, h = ImGui::GetTextLineHeight(), digit = ImGui::CalcTextSize("0").x;
    const float width = ImGui::CalcTextSize(title).x + float(count) * (h + digit + 12.0f) + 3.0f * pad;
    const ImVec2 at(imagePos.x + imageSize.x - width - pad, imagePos.y + imageSize.y - h - 3.0f * pad);
    if (at.x < imagePos.x || at.y < imagePos.y) return;  // no room in a tiny view
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(at, ImVec2(at.x + width, at.y + h + 2.0f * pad), IM_COL32(0, 0, 0, 170), 3.0f);
    float x = at.x + pad;
    draw->AddText(ImVec2(x, at.y + pad), IM_COL32(230, 230, 230, 255), title);
    x += ImGui::CalcTextSize(title).x + pad;
    for (int i = 0; i < count; ++i) {
        draw->AddRectFilled(ImVec2(x, at.y + pad + 2.0f), ImVec2(x + h - 4.0f, at.y + pad + h - 2.0f), cascadeColour(i));
        const std::string index = std::to_string(i);
        draw->AddText(ImVec2(x + h, at.y + pad), IM_COL32(230, 230, 230, 255), index.c_str());
        x += h + digit + 12.0f;
    }
    state_.controls.record("viewport.cascadeLegend", ControlRect{at.x, at.y, width, h + 2.0f * pad});
}

void Editor::drawOverlayNotes(ImVec2 imagePos, ImVec2 imageSize) {
    const AccuracyState& a = state_.accuracy;
    const bool shown = a.overlayShown();
    std::string note;
    const bool fullReport = a.report && a.report->ok && !a.report->live;
    if (!shown && a.running)
        note = "accuracy overlay: measuring...";
    else if (!a.overlayTexture)
        note = "accuracy overlay: no measurement yet (Measure in the Accuracy panel)";
    else if (!shown && a.overlayKind == OverlayKind::Soft && fullReport)
        note = "soft overlay: the measured light has no size, so there is no soft reference to compare with (set "
               "its size in the Light panel, then Measure)";
    else if (!shown)
        note = "this overlay comes with the next full measure (Measure in the Accuracy panel)";
    else if (!a.stale.empty())
        note = "Stale: " + a.stale;
    else if (a.report && a.report->live)
        note = "live numbers in the Accuracy panel; this overlay is the last full measure (again once the view is still)";
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float pad = 6.0f;
    // A dark box with text, wrapped to the view's width.
    const auto textBox = [&](ImVec2 at, const std::string& text, ImU32 colour, const char* control) {
        const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, imageSize.x - 4 * pad);
        draw->AddRectFilled(at, ImVec2(at.x + size.x + 2 * pad, at.y + size.y + 2 * pad), IM_COL32(0, 0, 0, 190), 3.0f);
        draw->AddText(nullptr, 0.0f, ImVec2(at.x + pad, at.y + pad), colour, text.c_str(), nullptr,
                      imageSize.x - 4 * pad);
        state_.controls.record(control, ControlRect{at.x, at.y, size.x + 2 * pad, size.y + 2 * pad});
    };
    if (!note.empty())
        textBox(ImVec2(imagePos.x + pad, imagePos.y + pad), note, IM_COL32(255, 190, 80, 255), "viewport.overlayNote");
    if (!shown) return;
    // The legend, bottom left, wrapping onto more lines when the view is narrow.
    const std::vector<LegendEntry>& keys = overlayLegend(a.uploadedKind);
    const float h = ImGui::GetTextLineHeight();
    const float maxX = imagePos.x + imageSize.x - pad;
    std::vector<std::pair<ImVec2, const LegendEntry*>> placed;
    float x = imagePos.x + 2 * pad, y = 0.0f, right = x;
    for (const LegendEntry& k : keys) {
        const float w = h + ImGui::CalcTextSize(k.name).x + 16.0f;
        if (x + w > maxX && !placed.empty()) {
            x = imagePos.x + 2 * pad;
            y += h + 2.0f;
        }
        placed.push_back({ImVec2(x, y), &k});
        x += w;
        right = std::max(right, x);
    }
    const float top = imagePos.y + imageSize.y - pad - (y + h) - pad;
    draw->AddRectFilled(ImVec2(imagePos.x + pad, top - pad * 0.5f), ImVec2(right + pad, top + y + h + pad * 0.5f),
                        IM_COL32(0, 0, 0, 170), 3.0f);
    for (const auto& [at, k] : placed) {
        const ImVec2 p(at.x, top + at.y);
        draw->AddRectFilled(ImVec2(p.x, p.y + 2), ImVec2(p.x + h - 4, p.y + h - 2), IM_COL32(k->red, k->green, k->blue, 255));
        draw->AddText(ImVec2(p.x + h, p.y), IM_COL32(230, 230, 230, 255), k->name);
    }
    state_.controls.record("viewport.legend", ControlRect{imagePos.x + pad, top - pad * 0.5f, right - imagePos.x,
                                                          y + h + pad});
    // The soft overlay's counts (its coloured pixels are what they count: soft_metrics.h's SoftMark) above the legend.
    if (a.uploadedKind == OverlayKind::Soft && a.report) {
        const std::string counts = softOverlayCounts(a.report->soft);
        const float height = ImGui::CalcTextSize(counts.c_str(), nullptr, false, imageSize.x - 4 * pad).y + 2 * pad;
        textBox(ImVec2(imagePos.x + pad, top - pad - height), counts, IM_COL32(230, 230, 230, 255),
                "viewport.softCounts");
    }
}
void Editor::drawStatusBar() {
    const ImVec2 size = ImGui::GetWindowSize();
    ImGui::SetCursorPos(ImVec2(8, size.y - kStatusHeight + 4));
    messageLogButton(state_);
    ImGui::SameLine();
    if (state_.loading) {
        const SceneLoadProgress& p = *state_.loading;
        ImGui::ProgressBar(float(std::fmod(p.elapsedSeconds, 1.0)), ImVec2(120, 16), "");
        ImGui::SameLine();
        ImGui::Text("loading %s (%s, %.1f s)", p.spec.c_str(), p.stage.c_str(), p.elapsedSeconds);
        return;
    }
    if (const Message* m = state_.statusMessage()) {
        // One line, clipped at the viewport's edge; the whole text on hover (and in the terminal).
        ImGui::PushStyleColor(ImGuiCol_Text, m->error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f)
                                                      : ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextUnformatted(m->text.c_str());
        ImGui::PopStyleColor();
        state_.controls.recordLastItem("status");
        const bool hovered = ImGui::IsItemHovered();
        if (state_.undo && state_.undo->note == m->text) {
            ImGui::SameLine();
            if (ImGui::SmallButton("Undo")) state_.undoLastStep();
            state_.controls.recordLastItem("status.undo");
        }
        if (hovered) {
            ImGui::BeginTooltip();
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
            ImGui::TextUnformatted(m->text.c_str());
            ImGui::PopTextWrapPos();
            const ImVec2 at = ImGui::GetWindowPos(), tipSize = ImGui::GetWindowSize();
            state_.controls.record("status.tooltip", ControlRect{at.x, at.y, tipSize.x, tipSize.y});
            ImGui::EndTooltip();
        }
    }
}

void Editor::drawPanels() {
    PanelContext ctx{state_, *this};
    // A panel asked for (the Probe after a click on the view) selects its tab this frame.
    const Panel* wanted = findPanel(state_.showPanel);
    state_.showPanel.clear();
    for (const Sidebar side : {Sidebar::Left, Sidebar::Right}) drawSidebar(side, ctx, wanted);
    drawSweepWindow(ctx);
}

// One sidebar: a window along the window's left or right edge with a tab per group of panels; the panels of the
// open tab stack under headers that carry what the old window titles did (the light edited, the preset's "*").
void Editor::drawSidebar(Sidebar side, PanelContext& ctx, const Panel* wanted) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float width = sidebarWidth(side, display);
    const bool left = side == Sidebar::Left;
    ImGui::SetNextWindowPos(ImVec2(left ? 0.0f : display.x - width, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(width, display.y));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::Begin(left ? "##leftSidebar" : "##rightSidebar", nullptr, flags);
    state_.controls.record(left ? "sidebar:left" : "sidebar:right",
                           ControlRect{ImGui::GetWindowPos().x, 0.0f, width, display.y});
    if (ImGui::BeginTabBar("##tabs", ImGuiTabBarFlags_FittingPolicyScroll)) {
        const bool dirty = state_.preset.dirty(state_.settings);
        for (const std::string& tab : sidebarTabs(side)) {
            const bool select = wanted && wanted->sidebar == side && tab == wanted->tab;
            // The Presets panel's tab carries the unsaved marker too (it shows while another tab is open).
            bool presets = false;
            for (const Panel* p : tabPanels(side, tab)) presets = presets || std::string(p->title) == "Presets";
            const std::string label = tab + (presets && dirty ? " *" : "") + "###" + tab;
            const bool open = ImGui::BeginTabItem(label.c_str(), nullptr, select ? ImGuiTabItemFlags_SetSelected : 0);
            state_.controls.recordLastItem("tab:" + tab);
            if (!open) continue;
            state_.controls.recordLastItem("tabOpen:" + tab);  // which tab a sidebar shows (scripts, tests)
            const std::vector<const Panel*> shown = tabPanels(side, tab);
            for (const Panel* panel : shown) {
                const ImVec2 start = ImGui::GetCursorScreenPos();
                std::string header = panel->title;
                if (std::string(panel->title) == "Presets" && state_.preset.dirty(state_.settings)) header += " *";
                if (panel->editsSelectedLight && state_.selected())
                    header += ": " + std::to_string(state_.selectedLight) + " " +
                              lightTypeText(state_.settings, state_.selectedLight);
                if (shown.size() > 1 || header != tab) {  // a lone panel named like its tab needs no header
                    if (panel != shown.front()) ImGui::Spacing();
                    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
                    ImGui::TextUnformatted(header.c_str());
                    ImGui::PopStyleColor();
                    ImGui::Separator();
                }
                ImGui::PushID(panel->title);
                panel->draw(ctx);
                ImGui::PopID();
                const float bottom = ImGui::GetCursorScreenPos().y;
                state_.controls.record(std::string("panel:") + panel->title,
                                       ControlRect{start.x, start.y, ImGui::GetContentRegionAvail().x, bottom - start.y});
            }
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::End();
}

void Editor::drawUnsavedChangesDialog() {
    if (!beginCentredModal("Unsaved changes", openUnsavedDialog_)) return;
    if (!pendingSwitch_) {
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    const PendingSwitch pending = *pendingSwitch_;
    ImGui::Text("The settings differ from preset \"%s\".", state_.preset.name().c_str());
    if (pending.kind == PendingSwitch::Scene)
        ImGui::Text("Save them before opening %s?", pending.target.c_str());
    else if (pending.kind == PendingSwitch::Preset)
        ImGui::Text("Save them before loading preset %s?", presetNameFromPath(pending.target).c_str());
    else
        ImGui::TextUnformatted("Save them before quitting?");
    ImGui::Spacing();
    const bool save = ImGui::Button("Save", ImVec2(110, 0));
    state_.controls.recordLastItem("dialog.save");
    ImGui::SameLine();
    const bool discard = ImGui::Button("Don't save", ImVec2(110, 0));
    state_.controls.recordLastItem("dialog.dontSave");
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel", ImVec2(110, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    state_.controls.recordLastItem("dialog.cancel");
    if (save || discard || cancel) {
        ImGui::CloseCurrentPopup();
        pendingSwitch_.reset();
    }
    ImGui::EndPopup();
    if (save) {
        if (state_.preset.canSaveInPlace()) {
            savePreset();
            if (!state_.preset.dirty(state_.settings)) performSwitch(pending);
        } else {
            afterSaveAs_ = pending;  // finished once Save As succeeds
            openSaveAs();
        }
    } else if (discard) {
        performSwitch(pending);
    }
}

void Editor::drawSaveAsDialog() {
    if (!beginCentredModal("Save preset as", openSaveAsDialog_)) return;
    if (state_.preset.shipped())
        ImGui::Text("\"%s\" is a shipped preset (read-only): save a copy in your folder.", state_.preset.name().c_str());
    ImGui::TextDisabled("folder: %s", state_.userPresetsDir.c_str());
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(300.0f);
    bool submit = ImGui::InputText("name", &saveAsName_, ImGuiInputTextFlags_EnterReturnsTrue);
    state_.controls.recordLastItem("saveAs.name");
    ImGui::SameLine();
    ImGui::TextDisabled(".json");
    bool overwrite = false;
    if (!saveAsError_.empty()) {
        errorText(saveAsError_);
        overwrite = ImGui::Button("Replace it");
        state_.controls.recordLastItem("saveAs.replace");
    }
    submit |= ImGui::Button("Save", ImVec2(110, 0));
    state_.controls.recordLastItem("saveAs.save");
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel", ImVec2(110, 0));
    state_.controls.recordLastItem("saveAs.cancel");
    if (submit || overwrite) {
        saveAsError_ = presetNameProblem(saveAsName_);
        if (saveAsError_.empty()) {
            const std::string path = (std::filesystem::path(state_.userPresetsDir) / (saveAsName_ + ".json")).string();
            const Settings saved = settingsToSave();
            saveAsError_ = state_.preset.saveAs(path, saved, overwrite, state_.sceneSpec);
            if (saveAsError_.empty()) {
                state_.settings = saved;
                dropAutosave();
                state_.say("saved preset " + path);
                refreshPresetList();
                ImGui::CloseCurrentPopup();
                if (afterSaveAs_) {
                    const PendingSwitch pending = *afterSaveAs_;
                    afterSaveAs_.reset();
                    ImGui::EndPopup();
                    performSwitch(pending);
                    return;
                }
            }
        }
    }
    if (cancel) {
        afterSaveAs_.reset();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void Editor::drawRestoreDialog() {
    if (!beginCentredModal("Restore unsaved work", openRestoreDialog_)) return;
    if (!restoreOffer_) {
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    const Autosave& a = *restoreOffer_;
    ImGui::TextUnformatted("ShadowLab did not exit cleanly last time.");
    ImGui::Text("Unsaved settings were kept at %s (preset %s, scene %s).", a.savedAt.c_str(),
                a.presetPath.empty() ? "built-in defaults" : presetNameFromPath(a.presetPath).c_str(),
                a.scene.c_str());
    ImGui::TextDisabled("%s", autosavePath_.c_str());
    ImGui::Spacing();
    const bool restore = ImGui::Button("Restore", ImVec2(110, 0));
    state_.controls.recordLastItem("restore.restore");
    ImGui::SameLine();
    const bool discard = ImGui::Button("Discard", ImVec2(110, 0));
    state_.controls.recordLastItem("restore.discard");
    if (restore || discard) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    if (restore) {
        restoreAutosave();
    } else if (discard) {
        const std::string savedAt = a.savedAt;
        restoreOffer_.reset();
        dropAutosave();
        state_.say("discarded the unsaved settings kept at " + savedAt);
    }
}

}  // namespace shadowlab::editor
