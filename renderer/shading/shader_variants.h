#pragma once
// Main-pass shader variants: the #defines a frame needs, and a cache of the programs built from them. Only the
// features the scene and settings use are compiled in: the light set (how many directional, spot and point lights,
// how many of each cast), the map arrays, the filter technique's taps, the view (no runtime branches on them).
#include "gl/gl_objects.h"
#include "settings/settings.h"

#include <map>
#include <string>
#include <vector>

namespace shadowlab {

// The lights a variant is built for, counted per kind; casters come first within each kind.
struct LightSetKey {
    int directional = 0, directionalCasters = 0;
    int spot = 0, spotCasters = 0;
    int point = 0, pointCasters = 0;
    int mapArrays2D = 0;    // sampler2DArrayShadow groups (directional and spot views)
    int mapArraysCube = 0;  // samplerCubeArrayShadow groups (point lights)
    int cascades = 0;       // every cascaded light's cascades together (the Cascades block's length)
    int lights() const { return directional + spot + point; }
    auto operator<=>(const LightSetKey&) const = default;
};

struct MainVariantKey {
    FilterKind filter = FilterKind::Pcf;
    int kernel = 3;  // FilterKind::Pcf only (other filters' taps do not depend on it)
    ViewMode view = ViewMode::Lit;
    LightSetKey lights;
    bool normalOffset = false;  // some casting light offsets its lookup
    bool receiverPlane = false; // some casting directional / spot light uses receiver-plane bias with a filter that
                                // supports it (RECEIVER_PLANE; each light's flag picks it at run time)
    bool alphaMask = false;
    bool alphaTexture = false;

    std::vector<std::string> defines() const;
    std::string name() const;  // the defines joined (tap offsets shortened), for FrameStats and logs
    auto operator<=>(const MainVariantKey&) const = default;
};

// Uniform locations of a main-pass program, looked up once when it is built (-1 where the variant lacks one).
struct MainUniforms {
    GLint viewProjection, model, normalMatrix, uvTransform, maps2D, mapsCube, cameraPosition, baseColor, ambient,
        filterScale, alphaFactor, alphaCutoff, baseColorTexture, cameraForward, pixelPerDepth, cascadeEye,
        cascadeForward;
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
