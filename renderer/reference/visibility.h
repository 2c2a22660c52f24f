#pragma once
// Exact visibility V of every surface sample: one shadow ray toward the light (directional: along -direction; spot:
// the segment to the light's position, and outside the cone = unlit; point: the segment to its position, no cone),
// started off the surface along the normal so it cannot hit its own triangle. Traced on all cores.
// A spot or point light with a range does not reach a point farther than that: such a point is neither lit nor
// shadowed by it (OutOfRange) and no metric of that light counts it.
#include "reference/embree_scene.h"
#include "reference/surface_samples.h"
#include "settings/settings.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace shadowlab {

enum class PixelClass : std::uint8_t {
    Background,   // no surface
    NonFinite,    // a non-finite point or normal
    FacingAway,   // the visible side faces away from the light: unlit, not scored (V = 0 for the boundary)
    OutOfRange,   // spot / point light: farther than its range; the light does not reach it: not scored
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
    LightType type = LightType::Directional;
    glm::dvec3 direction{0.0, -1.0, 0.0};  // unit, the direction light travels (spot: the cone axis); not point
    glm::dvec3 position{0.0};              // spot and point
    double cosHalfCone = 0.0;              // spot
    double range = 0.0;                    // spot and point: farther points are out of range; 0 = no limit

    // Spot and point lights shine from a position: their shadow rays are segments to it.
    bool positional() const { return type != LightType::Directional; }
    bool operator==(const ReferenceLight&) const = default;
};

// The reference's view of one light of the settings, relative to the render origin (the spot cone clamped as the
// light space clamps it).
ReferenceLight referenceLight(const LightSettings& light, const glm::dvec3& origin);

// Is `point` farther from a spot / point light than its range (never for a directional light or range 0)?
bool beyondRange(const ReferenceLight& light, const glm::dvec3& point);

struct VisibilityResult {
    std::vector<PixelClass> classes;  // per pixel
    std::vector<float> lambert;       // max(n . l, 0) per pixel (for the overlay's dimmed picture)
    std::size_t rays = 0;
    double milliseconds = 0.0;
    int threads = 0;
    bool cancelled = false;
};

// Exact visibility of one point with normal n facing the camera, by the same rules as traceVisibility: lit only
// when it faces the light, lies inside a spot's cone and within the range, and no opaque caster is in the way.
bool litAt(const EmbreeScene& bvh, const ReferenceLight& light, const glm::dvec3& point, const glm::dvec3& normal,
           double sceneRadius);

// Unit vector from a point toward the light.
glm::dvec3 towardLight(const ReferenceLight& light, const glm::dvec3& point);

// Where a shadow ray from `point` (normal n, facing the light) starts: off the surface along the normal, far enough
// for float's rounding (1e-5 x (|p| + sceneRadius)), so it cannot hit its own triangle. The soft reference's rays
// start here too.
glm::dvec3 shadowRayOrigin(const glm::dvec3& point, const glm::dvec3& normal, double sceneRadius);

// sceneRadius scales the ray's start offset (1e-5 x (|p| + radius) along the normal). cancel may be null.
VisibilityResult traceVisibility(const EmbreeScene& bvh, const SurfaceSamples& samples, const ReferenceLight& light,
                                 double sceneRadius, const std::atomic<bool>* cancel);

}  // namespace shadowlab
