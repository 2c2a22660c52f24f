#pragma once
// `shadowlab probe`: why one pixel is shadowed — its surface point, light-space position and texel, the receiver's
// depth, every filter tap's stored depth and comparison, each bias term at this surface, and S recomputed on the CPU
// next to the GPU's value; with --measure also the exact visibility and the error's cause.
#include <string>
#include <vector>

namespace shadowlab::cli {

struct ProbeOptions {
    std::string scene = "builtin:textbook";
    std::string preset;
    std::vector<std::string> overrides;
    int width = 1280;
    int height = 720;
    std::string pixel;  // "X,Y", y down from the top
    std::string json;   // optional
    bool measure = false;
    int light = -1;     // --light N: probe light N only (index into the effective lights); -1 = every casting light
    std::string view;   // --view: a cube face or cascade:N to look up in; "" = the view holding the point
};

// --view's help, shared by the per-light tools (probe, profile, export).
inline constexpr const char* kViewOptionHelp =
    "which of the light's views: a point light's cube face (+X, -X, +Y, -Y, +Z, -Z) or a cascaded light's cascade:N "
    "(default: every view, or the one holding the point)";

// "X,Y" -> the pixel; false (and `error` set, naming `option`) when it is not two integers.
bool parsePixel(const std::string& text, int& x, int& y, std::string& error, const std::string& option = "--pixel");

// Exit code 0 unless it failed (bad input or pixel, no GL, a file that cannot be written).
int runProbe(const ProbeOptions& options);

}  // namespace shadowlab::cli
