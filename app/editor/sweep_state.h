#pragma once
// What the "Cost vs accuracy" panel keeps between frames: the axes the user chose (preset keys and their values, as
// `shadowlab sweep --axis` takes them), the running sweep, the newest points and the chart's texture.
#include "editor/sweep_worker.h"
#include "gl/gl_objects.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::editor {

struct SweepAxisChoice {
    std::string key;     // "" = no axis
    std::string values;  // "V1,V2,..."
};

struct SweepPanelState {
    static constexpr int kMaxAxes = 3;
    bool open = false;  // the window is shown (the Accuracy panel's "Cost vs accuracy..." opens it)
    // Resolution 512..4096 and the filter kind; a third axis (depth format) one click away.
    std::vector<SweepAxisChoice> axes = {{"shadow.resolution", "512,1024,2048,4096"},
                                         {"filter.kind", "point,hardware2x2,pcf,poisson"},
                                         {"", ""}};
    int frames = 5;
    std::unique_ptr<SweepWorker> worker = std::make_unique<SweepWorker>();
    bool running = false;
    std::optional<SweepResult> result;  // the newest points (live while running)
    Settings base;                      // the settings the shown sweep started from
    std::string error;                  // why the newest Run was refused or failed
    std::string status;                 // progress / done line

    // The chart picture on the GPU, redrawn when the points, the marker or the size change.
    gl::Texture chart;
    int chartWidth = 0, chartHeight = 0;
    std::size_t chartPoints = 0;
    std::size_t chartMarker = 0;
    std::optional<std::size_t> hovered;  // the point under the mouse
};

}  // namespace shadowlab::editor
