#include "editor/panels/panel_registry.h"

#include <algorithm>

namespace shadowlab::editor {

const std::vector<Panel>& panels() {
    static const std::vector<Panel> all = {
        {"Scene", PanelColumn::Left, 0.17f, drawScenePanel},
        {"Presets", PanelColumn::Left, 0.25f, drawPresetsPanel},
        {"Lights", PanelColumn::Left, 0.19f, drawLightsPanel},
        {"Light", PanelColumn::Left, 0.21f, drawLightPanel, true},
        {"Projection", PanelColumn::Left, 0.18f, drawProjectionPanel, true},
        {"Shadow map", PanelColumn::Right, 0.35f, drawShadowMapPanel, true},
        {"Sampling", PanelColumn::Right, 0.17f, drawSamplingPanel},
        {"Shadow map viewer", PanelColumn::Right, 0.48f, drawShadowMapViewerPanel},
        // Bottom shares keep the outer panels' centres inside the middle 40 % of the window at 1280..1920 wide
        // (the viewport's side rule in editor_ui.cpp): Stats over 0.33, Probe over 0.26.
        {"Stats", PanelColumn::Bottom, 0.34f, drawStatsPanel},
        {"Accuracy", PanelColumn::Bottom, 0.36f, drawAccuracyPanel},
        {"Probe", PanelColumn::Bottom, 0.30f, drawProbePanel},
    };
    return all;
}

float leftColumnWidth(ImVec2 display) { return std::clamp(display.x * 0.23f, 300.0f, 400.0f); }
float rightColumnWidth(ImVec2 display) { return std::clamp(display.x * 0.26f, 320.0f, 440.0f); }
float bottomStripHeight(ImVec2 display) { return std::clamp(display.y * 0.32f, 200.0f, 320.0f); }

PanelRect firstRunRect(const Panel& panel, ImVec2 display) {
    const float left = leftColumnWidth(display);
    const float right = rightColumnWidth(display);
    if (panel.column == PanelColumn::Bottom) {
        // Side by side under the viewport, in registry order.
        const float h = bottomStripHeight(display);
        const float width = display.x - left - right;
        float x = left;
        for (const Panel& p : panels()) {
            if (p.column != PanelColumn::Bottom) continue;
            if (&p == &panel) return {ImVec2(x, display.y - h), ImVec2(panel.share * width, h)};
            x += p.share * width;
        }
    }
    // Stack the column's panels in registry order.
    float y = 0.0f;
    for (const Panel& p : panels()) {
        if (p.column != panel.column) continue;
        const float h = p.share * display.y;
        if (&p == &panel) {
            const float x = panel.column == PanelColumn::Left ? 0.0f : display.x - right;
            return {ImVec2(x, y), ImVec2(panel.column == PanelColumn::Left ? left : right, h)};
        }
        y += h;
    }
    return {ImVec2(0, 0), ImVec2(300, 200)};
}

}  // namespace shadowlab::editor
