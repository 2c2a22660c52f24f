#pragma once
// DESIGN.md's soft-light measures (version 3), from per-pixel buffers (no GL: unit-testable on synthetic buffers).
// V = the soft reference (reference/soft_visibility.h), S = the tool's shadow factor, e = 1/255, over the pixels the
// hard metrics score (MetricsResult::measured):
//   wrong pixels   = #{|S-V| >= 0.5} / #measured,   mean error = mean |S-V| over measured
//   bleeding       = #{V=0, S>e} / #{V=0}          (light in the true umbra: the VSM leak)
//   over-darkening = #{V=1, S<1-e} / #{V=1}        (acne, or a blur that spread a shadow onto lit ground)
//   penumbra width error = the technique's 0.1..0.9 transition width across true edges minus the reference's.
//
// How a transition width is measured on pixels (one profile per true-edge pixel):
//   1. True-edge pixels: measured pixels with V >= 0.5 that have a measured 4-neighbour with V < 0.5 (the reference's
//      0.5 contour passes between them).
//   2. The profile's direction d: the screen-space gradient of V there (central differences over measured
//      neighbours, one-sided at a missing one), normalized: it points from the umbra toward the lit side.
//   3. The profile: pixels round(p + t d) for t = -kProfileSteps..kProfileSteps, each side stopping before a pixel
//      that is outside the view, not measured, or off the edge pixel's surface (its normal more than 30 degrees from
//      the edge pixel's, or the point more than 0.1 x its distance off the edge pixel's tangent plane). A sample's
//      position s is the world distance walked along the profile (negative toward the umbra).
//   4. A field F (V or S) on the profile: its rising 0.5 crossing nearest t = 0 (F_t < 0.5 <= F_t+1); from there
//      toward the umbra the first sample with F <= 0.1 and toward the lit side the first with F >= 0.9, each position
//      interpolated linearly between its two samples. Width = s(0.9) - s(0.1), in world units; in texels divided by
//      the edge pixel's shadow-map texel size. A profile where either field has no such crossings is not counted.
//   5. Reported: the medians over the counted profiles of the reference's width, the technique's, and of the
//      per-profile difference technique - reference (the penumbra width error), in world units and texels.
#include "reference/pixel_vector.h"

#include <glm/ext/vector_double3.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace shadowlab {

inline constexpr int kSoftMetricsVersion = 3;
inline constexpr double kPenumbraLow = 0.1;   // the transition's ends: V or S from 0.1 ...
inline constexpr double kPenumbraHigh = 0.9;  // ... to 0.9
inline constexpr int kProfileSteps = 64;      // screen pixels a profile reaches on each side of its edge pixel

struct SoftCounts {
    std::size_t measured = 0;      // pixels scored (as the hard metrics score them)
    std::size_t umbra = 0;         // measured with V = 0 (no ray reaches the light)
    std::size_t fullyLit = 0;      // measured with V = 1 (every ray reaches it)
    std::size_t penumbra = 0;      // measured with 0 < V < 1
    std::size_t wrong = 0;         // |S - V| >= 0.5
    std::size_t bleeding = 0;      // V = 0, S > e
    std::size_t overDarkened = 0;  // V = 1, S < 1 - e
    std::size_t edgePixels = 0;    // true-edge pixels (step 1)
    std::size_t profiles = 0;      // profiles counted in the widths (step 4)
};

struct PenumbraWidths {
    double referenceWorld = 0.0, techniqueWorld = 0.0, errorWorld = 0.0;     // medians, world units
    double referenceTexels = 0.0, techniqueTexels = 0.0, errorTexels = 0.0;  // medians, shadow-map texels
};

// The soft numbers of one light (version 3). `measured` is false for a hard light (size 0), which keeps version 2's.
struct SoftAccuracy {
    bool measured = false;
    int metricsVersion = kSoftMetricsVersion;
    std::size_t light = 0;  // the light they describe (index in the effective lights)
    double size = 0.0;      // its lights.N.size: degrees (directional) or world units (spot, point)
    std::string sizeUnit;   // "degrees" or "world units"
    int rays = 0;           // rays per pixel of the reference
    double wrongPercent = 0.0;          // wrong / measured * 100
    double meanError = 0.0;             // mean |S - V| over measured
    double bleedingPercent = 0.0;       // bleeding / umbra * 100
    double overDarkeningPercent = 0.0;  // overDarkened / fullyLit * 100
    PenumbraWidths penumbra;
    SoftCounts counts;
    double traceMs = 0.0;  // the soft reference's rays (0 when reused from the cache)
    std::size_t tracedRays = 0;
    int threads = 0;
};

struct SoftMetricsInput {
    int width = 0;
    int height = 0;
    const std::vector<std::uint8_t>* measured = nullptr;  // per pixel: scored (MetricsResult::measured)
    const std::vector<float>* visibility = nullptr;       // the soft V
    const std::vector<float>* shadowFactor = nullptr;     // the tool's S
    const PixelVector<glm::dvec3>* points = nullptr;      // surface point per pixel (row 0 = top)
    const PixelVector<glm::dvec3>* normals = nullptr;     // unit geometric normal per pixel
    std::function<double(std::size_t)> worldPerTexel;     // shadow-map texel size at pixel i (world units)
};

// One pixel's verdict against the soft reference: bleeding (V = 0, S > e), over-darkened (V = 1, S < 1 - e) or
// neither. computeSoftMetrics counts these; the soft overlay (accuracy_overlay.h) colours them.
enum class SoftMark : std::uint8_t { None, Bleeding, OverDarkened };
SoftMark softMark(double visibility, double shadowFactor);

// The numbers (SoftAccuracy's light, size, rays and cost are left for the caller).
SoftAccuracy computeSoftMetrics(const SoftMetricsInput& input);

}  // namespace shadowlab
