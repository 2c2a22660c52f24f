#pragma once
// Main-pass shader variants: the #defines a frame needs, and a cache of the programs built from them. Only the
// features the scene and settings use are compiled in (no runtime branches on filter kind, kernel, view).
#include "gl/gl_objects.h"
#include "settings/settings.h"

#include <map>
#include <string>
#include <vector>

namespace shadowlab {

struct MainVariantKey {
    FilterKind filter = FilterKind::Pcf;
    int kernel = 3;
    ViewMode view = ViewMode::Lit;
    bool perspectiveLight = false;
    bool normalOffset = false;
    bool alphaMask = false;
    bool alphaTexture = false;

    std::vector<std::string> defines() const;
    std::string name() const;  // the defines joined, for FrameStats and logs
    auto operator<=>(const MainVariantKey&) const = default;
};

// Uniform locations of a main-pass program, looked up once when it is built (-1 where the variant lacks one).
struct MainUniforms {
    GLint viewProjection, model, normalMatrix, uvTransform, lightViewProjection, shadowMap, lightDirection,
        lightPosition, cameraPosition, shadowTexel, baseColor, lightIntensity, ambient, lightDepthRange,
        normalOffsetTexels, texelWorldSize, spotCosHalfAngle, poissonRadiusTexels, alphaFactor, alphaCutoff,
        baseColorTexture;
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
