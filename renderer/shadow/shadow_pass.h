#pragma once
// The depth-only pass from the light into the shadow map: D3D-style depth bias through glPolygonOffsetClamp,
// cull mode (flipped for mirrored instances), depth clamp, alpha-tested MASK casters, and casters outside the
// light's volume skipped. Draws that do not cast (GpuDraw::casts: casters.excluded) are never drawn. The casters a
// view holds go out batched (frame/depth_casters.h): one multi-draw call per face-cull state for the opaque ones, one
// per material and cull state for the alpha-tested ones, every model matrix read from the scene's transform buffer.
#include "frame/depth_casters.h"
#include "frame/gpu_scene.h"
#include "gl/gl_objects.h"
#include "light/light_space.h"
#include "shadow/shadow_map.h"
#include "views/shadow_planner.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

// A draw's bounding sphere, as the planner tests it against each view's volume (views/shadow_planner.h).
CasterSphere casterSphere(const GpuDraw& draw);
std::vector<CasterSphere> casterSpheres(const GpuScene& scene);  // of the draws that cast

// Clears a map to the far depth (1, or 0 reversed-Z): a view with no caster in its volume reads as lit everywhere.
void clearShadowMap(const ShadowMap& map, bool reversedZ);

// The draws a shadow view holds, as indices into GpuScene::draws(): those that cast and whose bounding sphere meets
// the light's volume (casterInVolume), in the scene's order. The one selection the pass and bench --planner's bare
// draw take their casters from; a caller may narrow it (e.g. to a cachedStatic view's static or dynamic casters)
// and restrict where it is drawn (docs/moving-scenes.md) before ShadowPass::run.
struct CasterSelection {
    std::vector<std::uint32_t> draws;
    int skipped = 0;                   // casting draws outside the light's volume
    std::optional<TexelRect> scissor;  // only these texels are cleared and written; nullopt: all
    bool clear = true;                 // false: draw over what the map holds (a copy of the cached static depth)
};
CasterSelection castersInVolume(const GpuScene& scene, const LightSpace& light);

struct ShadowPassCounts {
    int castersDrawn = 0;
    int castersSkipped = 0;       // outside the light's volume
    int alphaTestedCasters = 0;
    std::size_t trianglesDrawn = 0;
    int drawCalls = 0;            // multi-draw calls: one per group of draws that share their state
};

class ShadowPass {
public:
    ShadowPass();

    // Clears the map and draws the casters in the light's volume (castersInVolume).
    ShadowPassCounts run(const GpuScene& scene, const LightSpace& light, const ShadowMapSettings& shadow,
                         bool depthClamp, ShadowMap& map);
    // The same with the caller's selection of draws.
    ShadowPassCounts run(const GpuScene& scene, const CasterSelection& casters, const LightSpace& light,
                         const ShadowMapSettings& shadow, bool depthClamp, ShadowMap& map);

    // Whether glPolygonOffsetClamp (or its EXT twin) exists; without it DepthBiasClamp is ignored (with a warning).
    bool hasPolygonOffsetClamp() const { return hasOffsetClamp_; }

private:
    DepthCasters casters_;
    bool hasOffsetClamp_ = false;
};

}  // namespace shadowlab
