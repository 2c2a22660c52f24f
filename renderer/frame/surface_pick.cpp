#include "frame/surface_pick.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace shadowlab {

glm::dvec3 unprojectPixel(const FrameStats& stats, int x, int y, int width, int height, double depth) {
    // The main pass keeps GL's default clip convention: window depth 0..1 is NDC -1..1.
    const glm::dvec4 ndc((x + 0.5) / width * 2.0 - 1.0, 1.0 - (y + 0.5) / height * 2.0, depth * 2.0 - 1.0, 1.0);
    const glm::dvec4 world = glm::inverse(stats.cameraViewProjection) * ndc;
    return glm::dvec3(world) / world.w + stats.renderOrigin;
}

std::optional<glm::dvec3> pickSurface(const RenderTarget& target, const FrameStats& stats, int x, int y) {
    const int w = target.width(), h = target.height();
    if (!stats.ok || x < 0 || y < 0 || x >= w || y >= h) return std::nullopt;
    const float depth = target.readDepth(x, h - 1 - y);
    if (!(depth < 1.0f)) return std::nullopt;  // cleared: no surface there
    const glm::dvec3 point = unprojectPixel(stats, x, y, w, h, double(depth));
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) return std::nullopt;
    return point;
}

}  // namespace shadowlab
