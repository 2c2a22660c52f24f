#pragma once
// Every editor panel, listed once. A panel is drawn by one function in its own file; the editor hosts it in a tab of
// one of the two sidebars beside the viewport (panels sharing a tab stack in registry order, the last one gets the
// height left). Adding a panel = one file plus one line in panel_registry.cpp.
#include "editor/editor_state.h"

#include <imgui.h>

#include <string>
#include <vector>

namespace shadowlab::editor {

struct PanelContext {
    EditorState& state;
    EditorActions& actions;
};

enum class Sidebar { Left, Right };

struct Panel {
    const char* title;      // unique; its section's header (and the "panel:TITLE" control rect)
    Sidebar sidebar;        // which side of the viewport
    const char* tab;        // the sidebar tab that shows it
    void (*draw)(PanelContext&);  // the section's contents (the header is drawn by the editor)
    bool editsSelectedLight = false;  // its header names the light it edits ("Light: 1 spot")
};

const std::vector<Panel>& panels();
// A sidebar's tabs, in registry order, each once.
std::vector<std::string> sidebarTabs(Sidebar side);
// The panels one tab shows, in registry order.
std::vector<const Panel*> tabPanels(Sidebar side, const std::string& tab);
const Panel* findPanel(const std::string& title);

// A sidebar's width for a window of `display` size: wide enough that its panels' labels fit at 1280x720.
float sidebarWidth(Sidebar side, ImVec2 display);

// One function per panel, each in its own file.
void drawScenePanel(PanelContext&);
void drawTimelinePanel(PanelContext&);
void drawOutlinerPanel(PanelContext&);
void drawPresetsPanel(PanelContext&);
void drawLightsPanel(PanelContext&);
void drawLightPanel(PanelContext&);
void drawProjectionPanel(PanelContext&);
void drawShadowMapPanel(PanelContext&);
void drawSamplingPanel(PanelContext&);
void drawShadowMapViewerPanel(PanelContext&);
void drawStatsPanel(PanelContext&);
void drawExportPanel(PanelContext&);
void drawAccuracyPanel(PanelContext&);
void drawProbePanel(PanelContext&);
// Not a sidebar panel: a window over the viewport, opened from the Accuracy panel ("Cost vs accuracy..."). Called
// every frame (it polls its sweep); it draws only while open.
void drawSweepWindow(PanelContext&);

}  // namespace shadowlab::editor
