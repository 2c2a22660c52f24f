#include "shadow/shadow_map_files.h"

#include "image/image_io.h"

namespace shadowlab {

namespace {

// Depth in GL order (row 0 at the bottom) as the files; files start with the top row.
// Reversed-Z maps keep their stored depth in the EXR; the PNG shows 1 - stored, so near is dark in both conventions.
ShadowMapFilesResult writeDepthFiles(int width, int height, const std::vector<float>& depth, const std::string& exrPath,
                                     const std::string& pngPath, bool reversedZ) {
    ShadowMapFilesResult result;
    if (!exrPath.empty()) {
        result.error = writeExrDepth(exrPath, width, height, depth.data(), /*flipVertically=*/true);
        if (!result.ok()) return result;
    }
    if (!pngPath.empty()) {
        std::vector<float> shown = depth;
        if (reversedZ)
            for (float& d : shown) d = 1.0f - d;
        result.pngRange = writtenDepthRange(shown);
        const std::vector<std::uint8_t> gray = depthToGray(shown, result.pngRange);
        result.error = writePng(pngPath, width, height, 1, gray.data(), /*flipVertically=*/true);
    }
    return result;
}

}  // namespace

ShadowMapFilesResult writeShadowMapFiles(const ShadowMap& map, const std::string& exrPath, const std::string& pngPath) {
    ShadowMapFilesResult result;
    if (exrPath.empty() && pngPath.empty()) return result;
    if (!map.valid()) {
        result.error = "there is no shadow map yet (no frame was rendered)";
        return result;
    }
    return writeDepthFiles(map.resolution(), map.resolution(), map.readDepth(), exrPath, pngPath, map.reversedZ());
}

const std::array<CrossCell, 6>& cubeCrossCells() {
    // Faces in GL order +X, -X, +Y, -Y, +Z, -Z; (column, row) with row 0 at the top of the picture.
    static const std::array<CrossCell, 6> cells = {{{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}}};
    return cells;
}

ShadowMapFilesResult writeCubeShadowMapFiles(const std::array<const ShadowMap*, 6>& faces, const std::string& exrPath,
                                             const std::string& pngPath) {
    ShadowMapFilesResult result;
    if (exrPath.empty() && pngPath.empty()) return result;
    for (const ShadowMap* face : faces)
        if (!face || !face->valid() || face->resolution() != faces[0]->resolution()) {
            result.error = "the point light has no complete cube map yet (no frame was rendered)";
            return result;
        }
    const int n = faces[0]->resolution();
    const bool reversedZ = faces[0]->reversedZ();
    const int width = 4 * n, height = 3 * n;
    // Empty cells read as "no caster": the far depth of the convention.
    std::vector<float> cross(std::size_t(width) * std::size_t(height), reversedZ ? 0.0f : 1.0f);
    for (std::size_t f = 0; f < 6; ++f) {
        const std::vector<float> depth = faces[f]->readDepth();
        const CrossCell cell = cubeCrossCells()[f];
        const int x0 = cell.column * n, y0 = (2 - cell.row) * n;  // GL order: row 0 at the bottom
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                cross[std::size_t(y0 + y) * std::size_t(width) + std::size_t(x0 + x)] =
                    depth[std::size_t(y) * std::size_t(n) + std::size_t(x)];
    }
    return writeDepthFiles(width, height, cross, exrPath, pngPath, reversedZ);
}

}  // namespace shadowlab
