#pragma once
// Every editor panel, listed once. A panel is one ImGui window drawn by one function in its own file; its first-run
// place is a slot in a column around the viewport (later places come from imgui.ini). Adding a panel = one file plus
// one line in panel_registry.cpp.
#include "editor/editor_state.h"

#include <imgui.h>

#include <vector>

namespace shadowlab::editor {

struct PanelContext {
    EditorState& state;
    EditorActions& actions;
};

enum class PanelColumn { Left, Right, Bottom };

struct Panel {
    const char* title;      // the window's name: unique, and its imgui.ini key
    PanelColumn column;     // where it starts on first run
    float share;            // its part of the column's height (Left / Right) or of the bottom strip's width (Bottom);
                            // a column's shares add up to 1
    void (*draw)(PanelContext&);  // the window's contents (Begin/End are done by the editor)
    bool editsSelectedLight = false;  // its title names the light it edits ("Light: 1 spot")
};

const std::vector<Panel>& panels();

// Where a panel starts on first run, for a window of `display` size: columns that never overlap.
struct PanelRect {
    ImVec2 pos, size;
};
PanelRect firstRunRect(const Panel& panel, ImVec2 display);

// Column widths and the bottom strip's height for the first-run layout.
float leftColumnWidth(ImVec2 display);
float rightColumnWidth(ImVec2 display);
float bottomStripHeight(ImVec2 display);

// One function per panel, each in its own file.
void drawScenePanel(PanelContext&);
void drawPresetsPanel(PanelContext&);
void drawLightsPanel(PanelContext&);
void drawLightPanel(PanelContext&);
void drawProjectionPanel(PanelContext&);
void drawShadowMapPanel(PanelContext&);
void drawSamplingPanel(PanelContext&);
void drawShadowMapViewerPanel(PanelContext&);
void drawStatsPanel(PanelContext&);
void drawAccuracyPanel(PanelContext&);
void drawProbePanel(PanelContext&);
// Not a column panel: a window over the viewport, opened from the Accuracy panel ("Cost vs accuracy..."). Called
// every frame (it polls its sweep); it draws only while open.
void drawSweepWindow(PanelContext&);

}  // namespace shadowlab::editor
