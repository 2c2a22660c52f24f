#include "shadow/shadow_map_files.h"

#include "image/image_io.h"

namespace shadowlab {

ShadowMapFilesResult writeShadowMapFiles(const ShadowMap& map, const std::string& exrPath, const std::string& pngPath) {
    ShadowMapFilesResult result;
    if (exrPath.empty() && pngPath.empty()) return result;
    if (!map.valid()) {
        result.error = "there is no shadow map yet (no frame was rendered)";
        return result;
    }
    const int size = map.resolution();
    const std::vector<float> depth = map.readDepth();
    // GL stores row 0 at the bottom; files start with the top row.
    if (!exrPath.empty()) {
        result.error = writeExrDepth(exrPath, size, size, depth.data(), /*flipVertically=*/true);
        if (!result.ok()) return result;
    }
    if (!pngPath.empty()) {
        result.pngRange = writtenDepthRange(depth);
        const std::vector<std::uint8_t> gray = depthToGray(depth, result.pngRange);
        result.error = writePng(pngPath, size, size, 1, gray.data(), /*flipVertically=*/true);
    }
    return result;
}

}  // namespace shadowlab
