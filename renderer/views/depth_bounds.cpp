#include "views/depth_bounds.h"

#include "views/cascade_views.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// The depth's position on the grid: k for 2^(k / steps).
double gridPosition(double depth) { return std::log2(depth) * kDepthBoundsStepsPerOctave; }
double gridValue(double position) { return std::exp2(position / kDepthBoundsStepsPerOctave); }

}  // namespace

DepthBounds depthBoundsWanted(const Settings& settings) {
    DepthBounds wanted = DepthBounds::Off;
    for (const LightSettings& light : settings.lights) {
        if (!light.enabled || !light.castsShadows || light.type != LightType::Directional ||
            light.projection.fit != ProjectionFit::Cascades)
            continue;
        if (light.projection.depthBounds == DepthBounds::SameFrame) return DepthBounds::SameFrame;
        if (light.projection.depthBounds == DepthBounds::PreviousFrame) wanted = DepthBounds::PreviousFrame;
    }
    return wanted;
}

double depthGridDown(double depth) { return gridValue(std::floor(gridPosition(depth))); }
double depthGridUp(double depth) { return gridValue(std::ceil(gridPosition(depth))); }

std::optional<ViewDepths> keptDepthBounds(const std::optional<ViewDepths>& kept, const std::optional<ViewDepths>& seen) {
    if (!seen) return std::nullopt;
    if (!(seen->nearest > 0.0) || !(seen->farthest >= seen->nearest) || !std::isfinite(seen->farthest)) return seen;
    // The far bound must hold what is seen (beyond the last cascade a receiver is lit); the near bound only places
    // the splits (cascade 0 always reaches back to the camera's near plane), so it may lag within a factor of 2.
    if (kept && seen->farthest <= kept->farthest && seen->farthest >= 0.5 * kept->farthest &&
        seen->nearest >= 0.5 * kept->nearest && seen->nearest <= 2.0 * kept->nearest)
        return kept;
    return ViewDepths{depthGridDown(seen->nearest), depthGridUp(seen->farthest)};
}

double viewDepthOfWindowDepth(const glm::dmat4& p, double windowDepth) {
    // A point on the view axis at depth z is (0, 0, -z); its clip z and w are p[2][2] (-z) + p[3][2] and
    // p[2][3] (-z) + p[3][3]; solved for z at ndc = clip z / clip w.
    const double ndc = 2.0 * windowDepth - 1.0;
    return (ndc * p[3][3] - p[3][2]) / (ndc * p[2][3] - p[2][2]);
}

std::optional<ViewDepths> cascadeDepthBounds(const LightSettings& light, const ViewCamera& camera,
                                             std::string* fallback) {
    if (light.type != LightType::Directional || light.projection.fit != ProjectionFit::Cascades ||
        light.projection.depthBounds == DepthBounds::Off)
        return std::nullopt;
    const double nearPlane = camera.nearPlane, distance = cascadeShadowDistance(light.projection, camera);
    auto fallBack = [&](const std::string& why) -> std::optional<ViewDepths> {
        if (fallback)
            *fallback = "projection.depthBounds: " + why + "; the cascades span the camera's near plane (" +
                        std::to_string(nearPlane) + ") to the shadow distance (" + std::to_string(distance) + ")";
        return std::nullopt;
    };
    if (light.projection.splits.x > 0.0f) return fallBack("manual splits (projection.splits) are kept as given");
    if (!camera.seenDepths) return fallBack("no depths measured yet (the first frame)");
    const ViewDepths seen = *camera.seenDepths;
    if (!std::isfinite(seen.nearest) || !std::isfinite(seen.farthest) || seen.farthest < seen.nearest)
        return fallBack("the camera sees nothing");
    if (!(seen.farthest > nearPlane) || !(seen.nearest < distance))
        return fallBack("the camera sees nothing between its near plane and the shadow distance");
    const ViewDepths bounds{std::max(nearPlane, depthGridDown(std::max(seen.nearest, nearPlane))),
                            std::min(distance, depthGridUp(seen.farthest))};
    // A wall in front of the camera: everything at one depth. The grid still gives the slice a step's width.
    if (!(bounds.farthest > bounds.nearest)) return fallBack("the seen depths span no range");
    return bounds;
}

}  // namespace shadowlab
