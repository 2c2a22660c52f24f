#pragma once
// `shadowlab bench`: what accuracy costs in time. Renders a scene repeatedly per configuration (shadow-map
// resolution x filter), re-running the shadow pass every frame, and prints median per-pass times and map memory.
#include "settings/settings.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace shadowlab::cli {

struct BenchOptions {
    std::string scene = "builtin:textbook";
    std::string preset;
    std::vector<std::string> overrides;
    int width = 1920;
    int height = 1080;
    int frames = 30;
    std::vector<int> resolutions = {1024, 2048, 4096, 8192};
    std::vector<std::string> filters = {"point", "hardware2x2", "pcf3", "pcf5", "pcf9", "poisson"};
    std::string json;  // optional: the table as JSON
    bool lights = false;  // many lights instead: per-view times, what the planner skips, main pass per light count
    bool planner = false;  // the planner's CPU time with 8 lights, each cascade's pass against a bare depth draw
    bool referenceUpdate = false;  // the exact reference's update after an animation step against a rebuild
    bool softReference = false;    // the soft reference's trace: one query per ray against a stream query per pixel
};

int runBench(const BenchOptions& options);

// The lights a bench JSON describes (its "lights" array): each effective light's index, type, whether it is enabled
// and casts, and its shadow views (1, a point light 6; 0 without a shadow).
nlohmann::json benchLightsJson(const Settings& effective);

}  // namespace shadowlab::cli
