#pragma once
// `shadowlab render`: one headless frame to PNG (view), EXR (raw shadow map) and PNG (viewable shadow map).
#include <string>
#include <vector>

namespace shadowlab::cli {

struct RenderOptions {
    std::string scene = "builtin:textbook";
    std::string preset;                  // empty = built-in defaults
    std::vector<std::string> overrides;  // key=value
    int width = 1280;
    int height = 720;
    std::string out = "view.png";
    std::string shadowMapExr;
    std::string shadowMapPng;
    int light = -1;  // whose map --shadow-map / --shadow-map-png write; -1 = not given (then the only casting light)
    std::string mapView;  // which of a cascaded light's maps they write ("cascade:N"); "" = cascade:0
    std::string compare;  // A/B: preset B, drawn right of the divider (A = --preset with --set)
    double split = 0.5;   // where the divider stands, 0..1 of the width
    bool measure = false; // with --compare: each side's acne / leak / wrong pixels against the exact reference
    std::string view;                    // lit | shadow | light-depth; empty = the preset's
};

// Returns the process exit code; messages go to stdout / stderr.
int runRender(const RenderOptions& options);

}  // namespace shadowlab::cli
