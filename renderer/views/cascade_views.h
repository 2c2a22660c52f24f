#pragma once
// Cascades: a directional light's views that follow the camera, each fitted to one slice of the camera's frustum
// between its near plane and the shadow distance (views/cascade_views.cpp builds them).
#include "views/shadow_view.h"

#include <array>
#include <string>
#include <vector>

namespace shadowlab {

// The eight corners of the camera frustum's slice between depths a and b (render-origin-relative): depth a's four
// then b's, each in the order (-x,-y), (-x,+y), (+x,-y), (+x,+y) of the camera's right and up.
std::array<glm::dvec3, 8> sliceCorners(const ViewCamera& camera, double a, double b);

// How far the light's cascades reach from the camera: projection.shadowDistance, or the camera's far plane (0).
double cascadeShadowDistance(const ProjectionSettings& projection, const ViewCamera& camera);

// The depths in front of the camera that the scene's bounds cover (their corners' nearest and farthest, the nearest
// no nearer than the camera's near plane); {0, 0} for empty bounds.
ViewDepths boundsDepthRange(const Bounds& bounds, const glm::dvec3& origin, const ViewCamera& camera);

// Each cascade's far depth from the camera, nearest first (projection.cascadeCount of them, the last at the shadow
// distance): the manual splits when given, else the practical scheme (Zhang et al.: a blend by splitLambda of the
// logarithmic split n (f/n)^(i/N) and the uniform split n + (f - n) i/N). With `scene` (the tight fit) the
// practical scheme spans only the depths the scene covers: with a tiny camera near plane its first cascades would
// otherwise hold empty air (HARD_CASES 18); the stable fit leaves that to splitLambda, the splits or the shadow
// distance, so that its cascades keep their size as the camera moves (a scene beyond the shadow distance or
// without depth leaves the camera's range). Strictly increasing and finite (HARD_CASES 18): the logarithmic term
// starts no nearer than f x float's epsilon (a near plane of 1e-307 would overflow f/n and give a cascade no float
// matrix can hold), and practical splits that round onto each other in a range a few ulps wide are merged (fewer
// than cascadeCount come back). Empty with `why` naming the key when the splits cannot be used (beyond the shadow
// distance, or the shadow distance not beyond the camera's near plane).
std::vector<double> cascadeFarDepths(const ProjectionSettings& projection, const ViewCamera& camera,
                                     std::string& why, const ViewDepths* scene = nullptr);

// The slices of cascadeFarDepths with each blend band: cascade i fades into i + 1 over the last blendBand share of
// its own depth range, so cascade i + 1's volume reaches back to where that band starts.
std::vector<CascadeSlice> cascadeSlices(const ProjectionSettings& projection, const ViewCamera& camera,
                                        std::string& why, const ViewDepths* scene = nullptr);

}  // namespace shadowlab
