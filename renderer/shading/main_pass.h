#pragma once
// The camera pass: each pixel is projected into light space and compared with the shadow map; shading is
// Lambert + Blinn-Phong with ambient, or one of the debug views (shadow factor, light-space depth).
#include "frame/gpu_scene.h"
#include "frame/render_target.h"
#include "light/light_space.h"
#include "shading/shader_variants.h"
#include "shadow/shadow_map.h"

#include <glm/ext/matrix_double4x4.hpp>

#include <set>
#include <string>

namespace shadowlab {

struct MainPassInput {
    const GpuScene* scene = nullptr;
    const LightSpace* light = nullptr;
    const ShadowMap* shadowMap = nullptr;
    const Settings* settings = nullptr;
    glm::dmat4 viewProjection{1.0};  // render-origin-relative
    glm::dvec3 cameraPosition{0.0};  // render-origin-relative
};

class MainPass {
public:
    // Draws into `target`; returns the names of the shader variants used.
    std::set<std::string> run(const MainPassInput& input, RenderTarget& target);
    std::size_t variantsBuilt() const { return variants_.size(); }

private:
    MainVariantCache variants_;
};

}  // namespace shadowlab
