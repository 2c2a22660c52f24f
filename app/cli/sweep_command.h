#pragma once
// `shadowlab sweep`: what accuracy costs. Times and measures every point of a cartesian product of preset-key axes
// against one exact reference, with the raster limit (a bare depth draw) beside each shadow pass and the Pareto
// front of cost against wrong pixels; a table on stdout (progress on stderr), JSON, CSV and a chart PNG.
#include <string>
#include <vector>

namespace shadowlab::cli {

struct SweepOptions {
    std::string scene = "builtin:textbook";
    std::string preset;
    std::vector<std::string> overrides;
    std::vector<std::string> axes;  // "KEY=V1,V2,..."
    int width = 1280;
    int height = 720;
    int frames = 10;
    std::string json, csv, chart;   // optional outputs
    int chartWidth = 1200;
    int chartHeight = 700;
    int play = 0;      // --play K: each point plays K frames of its animation (played_point.h); 0 = not played
    std::string step;  // --step S with --play, seconds per frame as typed ("" = 1/30)
};

// 0 on success; 2 for a bad axis, key, value or option (before any work); 1 when the work failed.
int runSweep(const SweepOptions& options);

}  // namespace shadowlab::cli
