#pragma once
// Main-pass shader variants: a cache of the programs built from their keys (shading/variant_key.h).
#include "gl/gl_objects.h"
#include "shading/variant_key.h"

#include <map>
#include <string>

namespace shadowlab {

// Uniform locations of a main-pass program, looked up once when it is built (-1 where the variant lacks one).
struct MainUniforms {
    GLint viewProjection, model, normalMatrix, uvTransform, maps2D, mapsCube, cameraPosition, baseColor, ambient,
        filterScale, alphaFactor, alphaCutoff, baseColorTexture, cameraForward, pixelPerDepth, cascadeEye,
        cascadeForward, technique, depth2D, depthCube;  // depth2D, depthCube: the maps read as depths (PCSS)
};

struct MainProgram {
    gl::Program program;
    MainUniforms uniforms;
    std::string name;  // MainVariantKey::name(), for FrameStats
};

class MainVariantCache {
public:
    // Builds on first use; later calls return the cached program.
    const MainProgram& program(const MainVariantKey& key);
    std::size_t size() const { return programs_.size(); }

private:
    std::map<MainVariantKey, MainProgram> programs_;
};

}  // namespace shadowlab
