#pragma once
// What the shadow map's bias amounts to. DepthBias, SlopeScaledDepthBias and DepthBiasClamp reach the GPU as
// glPolygonOffsetClamp(factor, units, clamp), which offsets each caster's stored depth by
//     o = min(factor * m + units * r, clamp)       (GL 4.5 section 14.6.5; clamp 0 = none)
// with m the triangle's largest depth slope (window depth per shadow-map texel) and r the format's minimum
// resolvable difference: one fixed-point step for D16 / D24, but for D32F 2^(e - 23) with e the float exponent of
// the triangle's largest depth, so the same DepthBias is a different depth at every receiver depth.
// The one place these conversions live: the renderer's frame report, the editor's Shadow map panel and the tuner.
#include "light/light_space.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <glm/ext/vector_double3.hpp>

#include <string>
#include <vector>

namespace shadowlab {

// One bias amount in the three units a user can judge it in.
struct BiasTerm {
    double depth = 0.0;   // normalized window depth of the shadow map, [0, 1]
    double world = 0.0;   // world units along the light
    double texels = 0.0;  // world / one shadow-map texel's world size there
};

// One float step of clip-space depth at window depth `depth`, in window depth (see BiasReport::clipPrecision): GL's
// [-1, 1] clip depth, or reversed-Z's zero-to-one clip depth (the window depth itself).
double clipDepthStepAt(double depth, bool reversedZ = false);

// r for a triangle whose largest window depth is `depth` (clamped into the format's range).
double depthStepAt(DepthFormat format, double depth);

// The polygon offset o a caster triangle gets: min(SlopeScaledDepthBias x slope + DepthBias x r(maxDepth), clamp).
double polygonOffsetDepth(const ShadowMapSettings& shadow, DepthFormat format, double maxDepth, double slope);

// m of a triangle from its vertices in the map's window space (x, y in texels, z window depth): the largest of
// |dz/dx|, |dz/dy|, as the GPU computes it for the polygon offset. Negative for an edge-on triangle (no slope).
double windowDepthSlope(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// A depth difference `depth`, taken at window depth `atDepth` (spot lights' depth is not linear in distance), in
// world units and texels.
BiasTerm biasTerm(const LightSpace& light, double depth, double atDepth);

// Where the scene's surfaces (every one can receive a shadow) lie in the shadow map: window depths (clamped to
// [0, 1] as depth clamp and the far-plane rule do) and depth slopes, weighted by the area each covers in the map.
struct ReceiverDepths {
    bool valid = false;        // false when no triangle lands inside the light's volume
    double minDepth = 0.0;
    double maxDepth = 0.0;
    double medianDepth = 0.0;
    double medianSlope = 0.0;  // m: window depth per texel, max(|dz/dx|, |dz/dy|) as the GPU computes it
};
// `light` is relative to `origin`, as the Renderer builds it.
ReceiverDepths receiverDepths(const Scene& scene, const LightSpace& light, const glm::dvec3& origin);

struct BiasReport {
    bool valid = false;           // receivers known
    ShadowMapSettings shadow;     // the settings it reports on
    DepthFormat format = DepthFormat::D32F;  // the map's real format
    double stepNear = 0.0;        // r at the nearest receivers (D16 / D24: the same everywhere)
    double stepFar = 0.0;         // r at the farthest receivers
    BiasTerm constantNear;        // DepthBias x r at the nearest receivers
    BiasTerm constantFar;         // ... at the farthest
    double medianSlope = 0.0;     // the receivers' median m
    BiasTerm slope;               // SlopeScaledDepthBias x m at the median receiver
    BiasTerm clamp;               // DepthBiasClamp (depth 0 = no clamp)
    BiasTerm total;               // what the median receiver's caster gets: constant + slope, clamped
    // The step of the float clip space at the receivers (GL's [-1, 1] depth: window depth = 0.5 ndc + 0.5, so near
    // depth 0 or 1 one float step of ndc is 2^-25 of depth however fine D32F's own step is). Caster and receiver
    // depths both carry this rounding: a bias below it cannot separate a surface from itself.
    BiasTerm clipPrecision;
    // The nearest and farthest receivers' stored depths (reversed-Z: nearest = the largest) and the median's.
    double receiverDepthMin = 0.0, receiverDepthMax = 0.0, receiverDepthMedian = 0.0;
    double normalOffsetWorld = 0.0;
    double texelWorldSize = 0.0;  // at the median receiver
};
BiasReport biasReport(const ShadowMapSettings& shadow, DepthFormat format, const LightSpace& light,
                      const ReceiverDepths& receivers);

// The report as lines of text, e.g. "SlopeScaledDepthBias 2 x median slope 1.2e-05 = 2.4e-05 depth = 0.024 world
// units = 0.6 texels": the CLI's frame report prints them, the editor's Shadow map panel shows them.
std::vector<std::string> describeBias(const BiasReport& bias);

// Texels one unit of DepthBias moves the median receiver's caster (the tuner searches in texels, writes units).
double depthBiasUnitTexels(const LightSpace& light, DepthFormat format, const ReceiverDepths& receivers);

}  // namespace shadowlab
