#pragma once
// The depth-bounds fit (SDSM-style, Lauritzen et al. 2011): a cascaded light's splits span the nearest and farthest
// depth the camera actually sees (ViewCamera::seenDepths, reduced on the GPU by frame/depth_bounds_pass) instead of
// the camera's near plane to the shadow distance. The bounds are quantized to a grid in log space, so that small
// changes of what is seen keep the same splits: the stable fit's cascade sizes (and texels) then do not change from
// frame to frame.
#include "settings/settings.h"
#include "views/view_camera.h"

#include <glm/ext/matrix_double4x4.hpp>

#include <optional>
#include <string>

namespace shadowlab {

// Grid steps per doubling of depth: a bound moves only when the seen depth crosses a step of 2^(1/4) (19 %).
constexpr int kDepthBoundsStepsPerOctave = 4;

// What the frame must measure: sameFrame when any casting cascaded light asks for it, else previousFrame when any
// asks for that, else off.
DepthBounds depthBoundsWanted(const Settings& settings);

// The grid value at or below (down) / at or above (up) a positive depth.
double depthGridDown(double depth);
double depthGridUp(double depth);

// The bounds a frame keeps, given the bounds it kept before and what it sees now (hysteresis on the grid): the kept
// bounds stay while the farthest seen depth lies within [half the kept far bound, the kept far bound] and the nearest
// within a factor of 2 of the kept near bound (it only places the splits: cascade 0 reaches back to the camera's
// near plane anyway); otherwise the seen depths snapped outward to the grid (nearest down, farthest up). Quantizing alone is not enough:
// a seen depth that drifts across a grid line would change the splits (and a stable fit's texel size) every time it
// crossed back and forth. Without seen depths: nullopt.
std::optional<ViewDepths> keptDepthBounds(const std::optional<ViewDepths>& kept, const std::optional<ViewDepths>& seen);

// The depth along the viewing direction of a window depth (0..1, GL's default depth range) under `projection`
// (perspective or orthographic, as frame/camera builds it).
double viewDepthOfWindowDepth(const glm::dmat4& projection, double windowDepth);

// The range a light's cascades span: nullopt when projection.depthBounds is off or the light is not cascaded. With
// the key on but manual splits, or no usable measurement (none yet, nothing seen, or nothing before the shadow distance)
// `fallback` says why and the range is nullopt: the cascades span the camera's near plane to the shadow distance.
// Otherwise the seen depths, nearest rounded down and farthest rounded up to the grid, within
// [camera near plane, shadow distance].
std::optional<ViewDepths> cascadeDepthBounds(const LightSettings& light, const ViewCamera& camera,
                                             std::string* fallback = nullptr);

}  // namespace shadowlab
