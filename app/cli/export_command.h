#pragma once
// `shadowlab export`: the preset's shadow state as a snippet for D3D12, D3D11, Vulkan or OpenGL, or as JSON.
#include <string>
#include <vector>

namespace shadowlab::cli {

struct ExportOptions {
    std::string scene = "builtin:textbook";  // the world-unit figures (normal offset, light volume) depend on it
    std::string preset;
    std::vector<std::string> overrides;
    std::string format;  // d3d12 | d3d11 | vulkan | gl | json
    std::string out;     // optional: written atomically; otherwise stdout
};

// Exit code 0, 1 when the work failed (scene, output file), 2 for a bad preset / --set / --format.
int runExport(const ExportOptions& options);

}  // namespace shadowlab::cli
