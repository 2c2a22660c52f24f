#pragma once
// What the Probe panel and the shadow map viewer's tap highlights show: the newest pixel probe of the viewport
// (issue 13, "Why this pixel"), the view it was made for, and a pending request from a click or P held over a pixel.
#include "editor/accuracy_state.h"
#include "probe/depth_profile.h"
#include "editor/view_choice.h"
#include "probe/pixel_probe.h"

#include <glm/ext/vector_int2.hpp>

#include <optional>
#include <string>

namespace shadowlab::editor {

struct ProbeState {
    std::optional<glm::ivec2> request;      // a viewport pixel (y down) to probe on the next frame
    std::optional<PixelProbeReport> report;  // the newest probe
    std::optional<AccuracyViewKey> key;      // the view it was made for; a changed view re-probes the same pixel
    bool withMeasurement = false;            // the report carries the Accuracy panel's verdict for its pixel
    // The panel's view of the selected light (all views: the one holding the pixel, both cascades in a blend band);
    // probedView is the one the report was made with: another choice probes the same pixel again.
    ViewChoice view;
    std::string probedView;

    // The depth profile: Ctrl+drag in the viewport draws its line (y down); on release it is profiled.
    std::optional<glm::ivec2> lineFrom, lineTo;
    bool drawingLine = false;                   // the drag is in progress
    bool profileRequested = false;              // profile lineFrom -> lineTo on the next frame
    std::optional<DepthProfile> profile;        // the newest profile
    std::optional<AccuracyViewKey> profileKey;  // the view it was made for; a changed view profiles the line again
};

}  // namespace shadowlab::editor
