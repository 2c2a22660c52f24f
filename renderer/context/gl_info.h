#pragma once
// What the current GL context is and can do: for `shadowlab info`, limits checks and timing policy.
#include <string>

namespace shadowlab {

struct GlInfo {
    std::string vendor;
    std::string renderer;
    std::string version;
    std::string glslVersion;
    int maxTextureSize = 0;
    int maxArrayTextureLayers = 256;  // GL_MAX_ARRAY_TEXTURE_LAYERS (2048 on most desktop GPUs)
    int maxSamples = 0;
    bool polygonOffsetClamp = false;  // GL 4.6 / ARB / EXT_polygon_offset_clamp
    bool clipControl = false;         // GL 4.5 core
    bool softwareRasterizer = false;  // llvmpipe / softpipe / swrast: GPU timer queries are meaningless there
};

// Reads the current context (needs a loaded GL).
GlInfo queryGlInfo();

}  // namespace shadowlab
