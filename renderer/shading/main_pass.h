#pragma once
// The camera pass: each pixel is projected into each light's shadow view and compared with its map; shading is
// Lambert + Blinn-Phong per light with ambient, or one of the debug views (shadow factor, light-space depth).
#include "frame/gpu_scene.h"
#include "frame/render_target.h"
#include "light/light_space.h"
#include "shading/shader_variants.h"
#include "shadow/shadow_map.h"
#include "views/shadow_view.h"

#include <glm/ext/matrix_double4x4.hpp>

#include <set>
#include <string>
#include <vector>

namespace shadowlab {

// Where no surface is drawn. Not grey: the shadow view writes S as grey, so a reader tells drawn pixels by colour.
inline constexpr float kClearColour[4] = {0.10f, 0.11f, 0.13f, 1.0f};

// A cascade as the main pass sees it: its view and its layer in the light's map array.
struct MainPassCascade {
    const ShadowView* view = nullptr;
    int layer = 0;
};

// One light as the main pass sees it.
struct MainPassLight {
    const LightSettings* settings = nullptr;
    const LightSpace* space = nullptr;  // casting lights: the view it is compared in (a point light: any face)
    int mapArray = -1;                  // casting lights: index into MainPassInput::maps2D or ::mapsCube
    int layer = 0;                      // its layer in that array (a point light: its cube index)
    std::vector<MainPassCascade> cascades;  // a cascaded light's cascades, nearest first (all in mapArray)
};

struct MainPassInput {
    const GpuScene* scene = nullptr;
    const Settings* settings = nullptr;    // global settings (ambient, filter, view); lights come from `lights`
    MainVariantKey variant;                // the frame's: mainVariantKey(*settings); each draw adds its material's part
    std::vector<MainPassLight> lights;     // enabled lights; casting ones have a space and a map
    std::vector<GLuint> maps2D;            // sampler2DArrayShadow textures, in array-index order
    std::vector<GLuint> mapsCube;          // samplerCubeArrayShadow textures
    std::vector<GLuint> samplers2D;        // each array's compare sampler (its depth convention's: LEQUAL or GEQUAL)
    std::vector<GLuint> samplersCube;
    glm::dmat4 viewProjection{1.0};  // render-origin-relative
    glm::dvec3 cameraPosition{0.0};  // render-origin-relative
    glm::dvec3 cameraForward{0.0, 0.0, -1.0};  // unit: the texel density view measures depth along it
    // The camera the cascades were fitted to (render-origin-relative eye, unit forward): they are chosen by depth
    // along it. The view's own camera unless the cascades follow a frozen one.
    glm::dvec3 cascadeEye{0.0};
    glm::dvec3 cascadeForward{0.0, 0.0, -1.0};
    double pixelPerDepth = 0.0;  // a screen pixel's world size per unit of depth (texel density view)
    glm::dvec3 renderOrigin{0.0};    // subtracted from light positions
};

class MainPass {
public:
    MainPass();
    // Draws into `target`; returns the names of the shader variants used.
    std::set<std::string> run(const MainPassInput& input, RenderTarget& target);
    std::size_t variantsBuilt() const { return variants_.size(); }

private:
    MainVariantCache variants_;
    gl::Buffer lightBuffer_;    // the Lights uniform block
    gl::Buffer cascadeBuffer_;  // the Cascades uniform block (frames with a cascaded light)
    gl::Sampler depthSampler_;  // the maps read as depths (a technique's own lookup: PCSS's blocker search)
};

}  // namespace shadowlab
