#pragma once
// The exact-visibility reference's acceleration structure: an Embree 3 BVH over every instance's triangles, in
// render-origin-relative world space (the renderer's origin: the scene's bounds centre), with an occlusion filter
// that alpha-tests MASK materials at the hit. Built once per scene geometry; queries are thread-safe.
// firstHit() also answers what the shadow pass would do with the faces on a ray (cull mode, doubleSided, mirrored
// winding), so the accuracy meter can name why a pixel's shadow is wrong.
#include "reference/alpha_mask.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <glm/ext/vector_double3.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace shadowlab {

// Which faces a firstHit() query sees.
struct HitRules {
    bool ignoreAlpha = false;       // MASK faces block everywhere (the alpha test is skipped)
    bool shadowPassCulling = false; // drop the faces the shadow pass culls: cullMode, unless doubleSided; the
                                    // front face follows the instance's winding (mirrored instances flip it)
    CullMode cullMode = CullMode::None;
    bool positional = false;  // spot or point: light comes from lightPosition
    glm::vec3 lightDirection{0.0f, -1.0f, 0.0f};  // directional: where light travels
    glm::vec3 lightPosition{0.0f};                // spot and point
};

struct RayHit {
    bool hit = false;
    float t = 0.0f;            // along the query's direction (in its length units)
    unsigned geometry = 0;     // Embree geometry id (one per instance)
    unsigned primitive = 0;    // triangle of that instance's mesh
    bool alphaMask = false;    // the hit face's material is MASK
    bool doubleSided = false;
};

class EmbreeScene {
public:
    // Throws std::runtime_error if Embree cannot start. The scene must outlive this object (MASK filters read its
    // uvs and images). `castingInstances` (a flag per Scene::instances entry, scene/scene_casters.h; empty = all):
    // only the instances that cast are in the BVH, as only they are in the shadow maps.
    EmbreeScene(const Scene& scene, const glm::dvec3& origin, const std::vector<char>& castingInstances = {});
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // Is anything opaque on the segment origin + t * direction, t in (0, tFar)?
    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tFar) const;

    // The nearest face on origin + t * direction, t in (0, tFar), that the rules let through.
    RayHit firstHit(const glm::vec3& origin, const glm::vec3& direction, float tFar, const HitRules& rules) const;

    bool hasAlphaMask() const { return !masks_.empty(); }

    // Per geometry: what the shadow pass needs to decide culling (public for Embree's filter callbacks).
    struct GeometryInfo {
        const float* vertices = nullptr;    // world positions (Embree's buffer), xyz per vertex
        const unsigned* indices = nullptr;  // 3 per triangle
        bool mirrored = false;
        bool doubleSided = false;
        bool alphaMask = false;
    };
    const GeometryInfo& geometry(unsigned id) const { return geometries_[id]; }

    double buildMilliseconds() const { return buildMs_; }
    std::size_t triangles() const { return triangles_; }

private:
    void* device_ = nullptr;  // RTCDevice
    void* scene_ = nullptr;   // RTCScene
    std::vector<std::unique_ptr<AlphaMask>> masks_;
    std::vector<GeometryInfo> geometries_;
    double buildMs_ = 0.0;
    std::size_t triangles_ = 0;
};

}  // namespace shadowlab
