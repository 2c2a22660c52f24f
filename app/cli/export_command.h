#pragma once
// `shadowlab export`: every light's shadow state (each view, point lights' six cube faces) as a snippet for D3D12, D3D11, Vulkan or OpenGL, or as JSON.
#include <string>
#include <vector>

namespace shadowlab::cli {

struct ExportOptions {
    std::string scene = "builtin:textbook";  // the world-unit figures (normal offset, light volume) depend on it
    std::string preset;
    std::vector<std::string> overrides;
    std::string format;  // d3d12 | d3d11 | vulkan | gl | json
    std::string out;     // optional: written atomically; otherwise stdout
    int light = -1;      // --light N: only light N of the effective lights; -1 = every light
    std::string view;    // --view: with --light, one of its views (a cube face, cascade:N); "" = every view
    int width = 1280;    // the view a cascaded light's cascades are fitted to (its aspect ratio)
    int height = 720;
};

// Exit code 0 (also when no light casts: the output says so), 1 when the work failed (scene, output file), 2 for a
// bad preset / --set / --format / --light.
int runExport(const ExportOptions& options);

}  // namespace shadowlab::cli
