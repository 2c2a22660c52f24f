#pragma once
// `shadowlab profile`: the depth profile along a screen-space line — the receiver's light-space depth, the map's
// stored texels (a staircase) and receiver - bias, with acne and Peter Panning marked — as a PNG chart and JSON.
#include <string>
#include <vector>

namespace shadowlab::cli {

struct ProfileOptions {
    std::string scene = "builtin:textbook";
    std::string preset;
    std::vector<std::string> overrides;
    int width = 1280;
    int height = 720;
    std::string from, to;  // "X,Y", y down from the top
    std::string out;       // the chart, PNG
    std::string json;      // optional: every sample's numbers
    int plotWidth = 960;
    int plotHeight = 480;
    std::string view;  // --view: a cube face or cascade:N (default: the view holding each point)
    int light = -1;        // --light N; -1: the only shadow-casting light (several: refused, say which)
};

// Exit code 0 unless it failed (bad input or line, no GL, a file that cannot be written).
int runProfile(const ProfileOptions& options);

}  // namespace shadowlab::cli
