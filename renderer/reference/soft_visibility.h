#pragma once
// The soft reference (DESIGN.md, "Accuracy", soft lights, version 3): for a light of size > 0, V(p) = the fraction of
// N stratified rays from p toward points on the light's disc that reach it.
//   directional: the disc at unit distance along the direction toward the light, radius tan(angular diameter / 2)
//                (a cone of that angular diameter around the light's direction);
//   spot / point: a disc of the light's radius centred on its position, facing p.
// A ray that leaves below p's surface (n . d <= 0) is blocked by the receiver itself. Which pixels are scored, and
// the spot cone and range, follow the hard reference's verdict through the light's centre (visibility.h): only its
// Lit and Shadowed pixels trace rays; OutsideCone reads V = 0. Occlusion is EmbreeScene::occluded (MASK casters are
// alpha-tested at the hit there), from shadowRayOrigin as the hard rays.
// Sampling is deterministic: the N points are stratified over the disc (rows of cells on the unit square, mapped to
// the disc by Shirley and Chiu's concentric map) and jittered within their cells by a hash of (pixel, sample), so a
// result never depends on the thread count or the run. Size 0 is exactly the hard visibility (V = 1 where Lit).
#include "reference/embree_scene.h"
#include "reference/surface_samples.h"
#include "reference/visibility.h"
#include "settings/settings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <atomic>
#include <cstdint>
#include <vector>

namespace shadowlab {

// The light's disc as the soft reference samples it.
struct SoftLight {
    double discRadius = 0.0;  // directional: tan(angular diameter / 2), the disc at unit distance; spot / point: the
                              // radius in world units. 0 = a hard light.
    int rays = 0;             // N per pixel (reference.softRays)

    bool soft() const { return discRadius > 0.0; }
    bool operator==(const SoftLight&) const = default;
};

// From a light's size key (lights.N.size) and the ray count (reference.softRays).
SoftLight softLight(const LightSettings& light, int rays);

// The light's full penumbra width on a receiver `gap` world units behind an occluder's edge, the light straight
// across the edge: directional gap x 2 tan(diameter / 2); spot / point gap x 2 radius / distance (light to edge).
// (The analytic width the tests compare the reference with; `lightToEdge` is ignored for a directional light.)
double analyticPenumbraWidth(const ReferenceLight& light, const SoftLight& disc, double gap, double lightToEdge);

// Sample `k` of the N stratified points in the unit disc, jittered by `seed` (the pixel's index).
glm::dvec2 stratifiedDiscPoint(int k, int n, std::uint64_t seed);

struct SoftVisibilityResult {
    std::vector<float> visibility;  // per pixel, V in [0, 1]; 0 where the hard verdict is not Lit or Shadowed
    std::size_t rays = 0;
    double milliseconds = 0.0;
    int threads = 0;
    bool cancelled = false;
};

// The rays of one point toward the disc's N stratified samples, less those that leave below its surface (n . d <= 0:
// the receiver blocks them). All start at `origin` (shadowRayOrigin) and end at tFar (a segment to the disc's point
// for spot / point lights, unbounded for directional).
struct SoftRays {
    glm::vec3 origin{0.0f};
    float tFar = 0.0f;
    std::vector<glm::vec3> directions;
};
SoftRays softRays(const ReferenceLight& light, const SoftLight& disc, const glm::dvec3& point,
                  const glm::dvec3& normal, double sceneRadius, std::uint64_t seed);

// How a point's rays are traced: together through the stream query (the default), or one rtcOccluded1 each (how the
// reference was first traced; the bench and the tests compare the two).
enum class SoftTracing { Stream, EachRay };

// V of one point that faces the light (n . l > 0), inside a spot's cone and within range: the fraction of the disc's
// N rays that reach the light (softRays, traced together by EmbreeScene's stream query). `seed` picks the jitter
// (the pixel's index in traceSoftVisibility).
float softVisibilityAt(const EmbreeScene& bvh, const ReferenceLight& light, const SoftLight& disc,
                       const glm::dvec3& point, const glm::dvec3& normal, double sceneRadius, std::uint64_t seed,
                       SoftTracing tracing = SoftTracing::Stream);

// V of every pixel, from the hard verdicts `classes` of the same samples and light (traceVisibility). threads <= 0:
// every core. cancel may be null.
SoftVisibilityResult traceSoftVisibility(const EmbreeScene& bvh, const SurfaceSamples& samples,
                                         const std::vector<PixelClass>& classes, const ReferenceLight& light,
                                         const SoftLight& disc, double sceneRadius, const std::atomic<bool>* cancel,
                                         int threads = 0, SoftTracing tracing = SoftTracing::Stream);

}  // namespace shadowlab
