#pragma once
// The depth-only pass from the light into the shadow map: D3D-style depth bias through glPolygonOffsetClamp,
// cull mode (flipped for mirrored instances), depth clamp, alpha-tested MASK casters, and casters outside the
// light's volume skipped. Draws that do not cast (GpuDraw::casts: casters.excluded) are never drawn.
#include "frame/gpu_scene.h"
#include "gl/gl_objects.h"
#include "light/light_space.h"
#include "shadow/shadow_map.h"
#include "views/shadow_planner.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace shadowlab {

// A draw's bounding sphere, as the planner tests it against each view's volume (views/shadow_planner.h).
CasterSphere casterSphere(const GpuDraw& draw);
std::vector<CasterSphere> casterSpheres(const GpuScene& scene);  // of the draws that cast

// Clears a map to the far depth (1, or 0 reversed-Z): a view with no caster in its volume reads as lit everywhere.
void clearShadowMap(const ShadowMap& map, bool reversedZ);

struct ShadowPassCounts {
    int castersDrawn = 0;
    int castersSkipped = 0;       // outside the light's volume
    int alphaTestedCasters = 0;
    std::size_t trianglesDrawn = 0;
};

// Which casters a run draws and where (a cachedStatic light's views: docs/moving-scenes.md).
struct CasterSelection {
    const std::vector<std::size_t>* draws = nullptr;  // indices into GpuScene::draws(); nullptr: every draw
    std::optional<TexelRect> scissor;                 // only these texels are cleared and written; nullopt: all
    bool clear = true;                                // false: draw over what the map holds
};

class ShadowPass {
public:
    ShadowPass();

    ShadowPassCounts run(const GpuScene& scene, const LightSpace& light, const ShadowMapSettings& shadow,
                         bool depthClamp, ShadowMap& map, const CasterSelection& selection = {});

    // Whether glPolygonOffsetClamp (or its EXT twin) exists; without it DepthBiasClamp is ignored (with a warning).
    bool hasPolygonOffsetClamp() const { return hasOffsetClamp_; }

private:
    // A shadow-pass program with its uniform locations, looked up once (-1 where the program lacks one).
    struct CasterProgram {
        gl::Program program;
        GLint lightViewProjection = -1, model = -1, uvTransform = -1, alphaFactor = -1, alphaCutoff = -1,
              baseColor = -1;
        explicit CasterProgram(gl::Program built);
    };

    CasterProgram depthOnly_;        // vertex stage only: no fragment work for opaque casters
    CasterProgram alphaFactorOnly_;  // MASK material without a texture
    CasterProgram alphaTextured_;    // MASK material with a base-colour texture
    bool hasOffsetClamp_ = false;
};

}  // namespace shadowlab
