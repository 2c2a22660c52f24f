#pragma once
// The exact-visibility reference's acceleration structure, in two levels as the scene is: one Embree 3 BVH per mesh
// (its triangles, centred on the mesh's own bounds) and a top-level scene of one instance per casting Scene instance,
// whose transform places the mesh in render-origin-relative world space (the renderer's origin: the scene's bounds
// centre). The transforms are composed in double and only the origin-relative result is stored in float, so large
// worlds stay exact. When only instance transforms change (an animation step), updateTransforms() re-commits the top
// level alone; no mesh BVH is rebuilt. MASK materials are alpha-tested at the hit by an occlusion filter.
// Queries are thread-safe. firstHit() also answers what the shadow pass would do with the faces on a ray (cull mode,
// doubleSided, mirrored winding), so the accuracy meter can name why a pixel's shadow is wrong.
#include "reference/alpha_mask.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <glm/ext/vector_double3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
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
    unsigned geometry = 0;     // the top level's instance id (one per casting instance): geometry(id) describes it
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
    // The same question for `count` rays from one origin (blocked[r] = 1 when ray r is), in one call of Embree's
    // stream API marked coherent: rays that start together toward a small area are traced as packets of the CPU's
    // SIMD width, which costs far less than one query each (the soft reference's N rays per pixel).
    void occluded(const glm::vec3& origin, const glm::vec3* directions, std::size_t count, float tFar,
                  std::uint8_t* blocked) const;

    // The nearest face on origin + t * direction, t in (0, tFar), that the rules let through.
    RayHit firstHit(const glm::vec3& origin, const glm::vec3& direction, float tFar, const HitRules& rules) const;

    bool hasAlphaMask() const { return !masks_.empty(); }

    // Whether only transforms changed since this was built: `scene`'s layoutFingerprint (scene/scene_fingerprint.h,
    // the one definition the GPU upload uses too: the same Scene object, mesh and image buffers, instance-to-mesh
    // map, depth-relevant material values) is the one it was built from, with the same casting instances. Then
    // updateTransforms() follows the motion.
    bool sameGeometry(const Scene& scene, const std::vector<char>& castingInstances = {}) const;

    // Places every instance at `scene`'s transform relative to `origin` and re-commits the top level only (no mesh
    // BVH is rebuilt); nothing is committed when no transform changed. Requires sameGeometry(scene, ...).
    // Returns how many instances moved.
    std::size_t updateTransforms(const Scene& scene, const glm::dvec3& origin);

    // Per top-level instance: what the shadow pass needs to decide culling (public for Embree's filter callbacks).
    struct GeometryInfo {
        const float* vertices = nullptr;    // the mesh BVH's positions, xyz per vertex (mesh space, centred)
        const unsigned* indices = nullptr;  // 3 per triangle
        glm::mat4 toWorld{1.0f};            // mesh BVH space -> render-origin-relative world, as Embree applies it
        std::size_t instance = 0;           // its Scene::instances entry
        unsigned mesh = 0;                  // its Scene::meshes entry
        bool mirrored = false;
        bool doubleSided = false;
        bool alphaMask = false;
    };
    const GeometryInfo& geometry(unsigned id) const { return geometries_[id]; }

    double buildMilliseconds() const { return buildMs_; }    // the constructor: every mesh BVH and the top level
    double updateMilliseconds() const { return updateMs_; }  // the last updateTransforms()
    std::size_t triangles() const { return triangles_; }     // over the casting instances
    std::size_t meshBvhs() const { return meshes_.size(); }  // mesh BVHs held (meshes some casting instance uses)
    // Over this object's life: mesh BVHs built (only the constructor builds them) and top-level commits.
    std::size_t meshBuilds() const { return meshBuilds_; }
    std::size_t topCommits() const { return topCommits_; }

private:
    struct MeshBvh;
    void* device_ = nullptr;  // RTCDevice
    void* scene_ = nullptr;   // RTCScene: the top level
    std::size_t layout_ = 0;  // layoutFingerprint of the scene it was built from (sameGeometry)
    std::vector<std::unique_ptr<MeshBvh>> meshes_;
    std::vector<int> meshBvhOf_;  // per Scene::meshes entry: its index in meshes_, -1 = none
    std::vector<std::unique_ptr<AlphaMask>> masks_;
    std::vector<GeometryInfo> geometries_;
    double buildMs_ = 0.0;
    double updateMs_ = 0.0;
    std::size_t triangles_ = 0;
    std::size_t meshBuilds_ = 0;
    std::size_t topCommits_ = 0;
};

}  // namespace shadowlab
