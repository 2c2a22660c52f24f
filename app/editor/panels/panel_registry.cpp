#include "editor/panels/panel_registry.h"

#include <algorithm>

namespace shadowlab::editor {

const std::vector<Panel>& panels() {
    // Left: what is drawn and lit, and the bias you tune; right: what you look at while tuning it (the map, the
    // accuracy numbers, the probe, the times), so the Shadow map tab and any right tab show together.
    static const std::vector<Panel> all = {
        {"Scene", Sidebar::Left, "Scene", drawScenePanel},
        {"Timeline", Sidebar::Left, "Scene", drawTimelinePanel},  // the file's animations: play, scrub
        {"Presets", Sidebar::Left, "Scene", drawPresetsPanel},  // last in its tab: its list takes the height left
        {"Outliner", Sidebar::Left, "Outliner", drawOutlinerPanel},  // the file's nodes: what casts
        {"Lights", Sidebar::Left, "Lights", drawLightsPanel},
        {"Light", Sidebar::Left, "Lights", drawLightPanel, true},
        {"Projection", Sidebar::Left, "Lights", drawProjectionPanel, true},
        {"Shadow map", Sidebar::Left, "Shadow map", drawShadowMapPanel, true},
        {"Sampling", Sidebar::Left, "Shadow map", drawSamplingPanel},
        {"Shadow map viewer", Sidebar::Right, "Map", drawShadowMapViewerPanel},
        {"Accuracy", Sidebar::Right, "Accuracy", drawAccuracyPanel},
        {"Probe", Sidebar::Right, "Probe", drawProbePanel},
        {"Stats", Sidebar::Right, "Stats", drawStatsPanel},
        {"Export", Sidebar::Right, "Export", drawExportPanel},  // the snippet takes the height left
    };
    return all;
}

std::vector<std::string> sidebarTabs(Sidebar side) {
    std::vector<std::string> tabs;
    for (const Panel& p : panels())
        if (p.sidebar == side && std::find(tabs.begin(), tabs.end(), p.tab) == tabs.end()) tabs.emplace_back(p.tab);
    return tabs;
}

std::vector<const Panel*> tabPanels(Sidebar side, const std::string& tab) {
    std::vector<const Panel*> out;
    for (const Panel& p : panels())
        if (p.sidebar == side && tab == p.tab) out.push_back(&p);
    return out;
}

const Panel* findPanel(const std::string& title) {
    for (const Panel& p : panels())
        if (title == p.title) return &p;
    return nullptr;
}

float sidebarWidth(Sidebar side, ImVec2 display) {
    // At 1280 wide the view keeps 560 px; the Shadow map panel's bias table needs 370, the Accuracy panel's six
    // tabs 350.
    return side == Sidebar::Left ? std::clamp(display.x * 0.27f, 370.0f, 440.0f)
                                 : std::clamp(display.x * 0.27f, 350.0f, 460.0f);
}

}  // namespace shadowlab::editor
