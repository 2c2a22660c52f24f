#pragma once
// The exact-visibility reference's acceleration structure: an Embree 3 BVH over every instance's triangles, in
// render-origin-relative world space (the renderer's origin: the scene's bounds centre), with an occlusion filter
// that alpha-tests MASK materials at the hit. Built once per scene geometry; queries are thread-safe.
#include "reference/alpha_mask.h"
#include "scene/scene.h"

#include <glm/ext/vector_double3.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace shadowlab {

class EmbreeScene {
public:
    // Throws std::runtime_error if Embree cannot start. The scene must outlive this object (MASK filters read its
    // uvs and images).
    EmbreeScene(const Scene& scene, const glm::dvec3& origin);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // Is anything opaque on the segment origin + t * direction, t in (0, tFar)?
    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tFar) const;

    double buildMilliseconds() const { return buildMs_; }
    std::size_t triangles() const { return triangles_; }

private:
    void* device_ = nullptr;  // RTCDevice
    void* scene_ = nullptr;   // RTCScene
    std::vector<std::unique_ptr<AlphaMask>> masks_;
    double buildMs_ = 0.0;
    std::size_t triangles_ = 0;
};

}  // namespace shadowlab
