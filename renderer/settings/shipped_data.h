#pragma once
// The data ShadowLab ships (presets/), found relative to the running binary: <the binary's folder>/../share/shadowlab
// (the relative path comes from the install layout, SHADOWLAB_DATA_FROM_BIN). An installed binary finds its own
// prefix's copy wherever the prefix was moved; a binary in the build tree finds <build>/share/shadowlab, whose entries
// CMake links to the source tree's (CMakeLists.txt). No absolute path is compiled in, so an installed binary never
// reads the source tree.
#include <filesystem>
#include <string>

namespace shadowlab {

struct ShippedData {
    std::filesystem::path dir;    // the folder found; empty when none
    std::filesystem::path tried;  // where it was looked for (empty when the binary's own path is unknown)
    std::string problem;          // "" or why there is none, naming the binary and the path tried
};

// Looked up once per process, from /proc/self/exe.
const ShippedData& shippedData();

// <shipped data>/presets, or "" when there is no shipped data folder (shippedData().problem says why).
std::filesystem::path shippedPresetsDir();

// The lookup itself, for a binary at `executable` (tests).
ShippedData findShippedData(const std::filesystem::path& executable);

}  // namespace shadowlab
