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
    int light = 0;  // whose map --shadow-map / --shadow-map-png write
    std::string view;                    // lit | shadow | light-depth; empty = the preset's
};

// Returns the process exit code; messages go to stdout / stderr.
int runRender(const RenderOptions& options);

}  // namespace shadowlab::cli
