#pragma once
// The shadow map as files: the raw stored depth as a 1-channel 32-bit float OpenEXR (channel "Z", first scanline =
// top of the map), and a viewable grey PNG (depths stretched over their used range, white = no caster). A reversed-Z
// map's EXR holds its stored depth (near 1, far 0); its PNG shows 1 - stored, near dark as in the normal convention.
// Used by `shadowlab render --shadow-map / --shadow-map-png` and by editor screenshots.
#include "image/depth_visualization.h"
#include "shadow/shadow_map.h"

#include <array>
#include <string>

namespace shadowlab {

struct ShadowMapFilesResult {
    std::string error;   // "" on success; else names the file and what went wrong
    DepthRange pngRange; // the depths the PNG stretched to black .. light grey
    bool ok() const { return error.empty(); }
};

// Reads the map back once and writes the files whose path is not empty. Never creates folders.
ShadowMapFilesResult writeShadowMapFiles(const ShadowMap& map, const std::string& exrPath, const std::string& pngPath);

// A point light's six faces as one unfolded cross, 4 x 3 faces: +Y above +Z; -X, +Z, +X, -Z in the middle row;
// -Y below +Z. Each face as stored (GL's cube-map orientation); empty cells hold 1 (no caster, white).
struct CrossCell {
    int column, row;  // row 0 = top of the picture
};
const std::array<CrossCell, 6>& cubeCrossCells();  // per face, GL order +X, -X, +Y, -Y, +Z, -Z
ShadowMapFilesResult writeCubeShadowMapFiles(const std::array<const ShadowMap*, 6>& faces, const std::string& exrPath,
                                             const std::string& pngPath);

}  // namespace shadowlab
