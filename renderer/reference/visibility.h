#pragma once
// Exact visibility V of every surface sample: one shadow ray toward the light (directional: along -direction; spot:
// the segment to the light's position, and outside the cone = unlit), started off the surface along the normal so it
// cannot hit its own triangle. Traced on all cores.
#include "reference/embree_scene.h"
#include "reference/surface_samples.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace shadowlab {

enum class PixelClass : std::uint8_t {
    Background,   // no surface
    NonFinite,    // a non-finite point or normal
    FacingAway,   // the visible side faces away from the light: unlit, not scored (V = 0 for the boundary)
    OutsideCone,  // spot light: outside the cone (V = 0, scored as shadowed)
    Lit,          // V = 1
    Shadowed,     // V = 0: a caster is in the way
};

inline bool isLit(PixelClass c) { return c == PixelClass::Lit; }
inline bool isScored(PixelClass c) {
    return c == PixelClass::Lit || c == PixelClass::Shadowed || c == PixelClass::OutsideCone;
}

// The light as the reference sees it, render-origin-relative.
struct ReferenceLight {
    bool spot = false;
    glm::dvec3 direction{0.0, -1.0, 0.0};  // unit, the direction light travels (spot: the cone axis)
    glm::dvec3 position{0.0};              // spot
    double cosHalfCone = 0.0;              // spot
};

struct VisibilityResult {
    std::vector<PixelClass> classes;  // per pixel
    std::vector<float> lambert;       // max(n . l, 0) per pixel (for the overlay's dimmed picture)
    std::size_t rays = 0;
    double milliseconds = 0.0;
    int threads = 0;
    bool cancelled = false;
};

// Exact visibility of one point with normal n facing the camera, by the same rules as traceVisibility: lit only
// when it faces the light, lies inside a spot's cone and no opaque caster is in the way.
bool litAt(const EmbreeScene& bvh, const ReferenceLight& light, const glm::dvec3& point, const glm::dvec3& normal,
           double sceneRadius);

// Unit vector from a point toward the light.
glm::dvec3 towardLight(const ReferenceLight& light, const glm::dvec3& point);

// sceneRadius scales the ray's start offset (1e-5 x (|p| + radius) along the normal). cancel may be null.
VisibilityResult traceVisibility(const EmbreeScene& bvh, const SurfaceSamples& samples, const ReferenceLight& light,
                                 double sceneRadius, const std::atomic<bool>* cancel);

}  // namespace shadowlab
