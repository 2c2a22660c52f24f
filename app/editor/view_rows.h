#pragma once
// The Stats panel's table of shadow views, one row per view (a light's map, each cube face, each cascade): what its
// map got this frame (reused, static + dynamic from its cached static depth, full) and why (the planner's reason),
// its map's memory and its pass time. Kept apart from the drawing so
// tests read exactly what the table shows.
#include "frame/frame_stats.h"

#include <map>
#include <string>
#include <vector>

namespace shadowlab::editor {

struct ViewRow {
    std::string name;          // "light 0 cascade:1"
    int cascade = -1;          // a cascade's index (the table marks it with its colour), -1 for other views
    bool ran = false;
    std::string update;        // what its map got this frame: "reused", "static + dynamic", "full"; "-" without a view
    std::string memory;        // its layer of the map array, "4.0 MiB"; "-" for a light without a view
    std::string milliseconds;  // "0.42"; "-" when it was never timed
    bool timeFromEarlier = false;  // the view was kept this frame: the time is of its newest run
    std::string why;
};

// `lastMilliseconds`: each view's newest measured pass time (EditorState::viewMilliseconds), shown for a view kept
// this frame so a still camera does not blank the cascades' times.
std::vector<ViewRow> viewRows(const FrameStats& stats, const std::map<ShadowViewId, double>& lastMilliseconds);

// "512 KiB", "4.0 MiB".
std::string memoryText(std::size_t bytes);

}  // namespace shadowlab::editor
