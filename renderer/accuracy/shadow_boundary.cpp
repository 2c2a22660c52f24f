#include "accuracy/shadow_boundary.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace shadowlab {

namespace {

bool visibleLight(PixelClass c) { return c == PixelClass::Lit; }
bool hasVisibility(PixelClass c) { return c != PixelClass::Background && c != PixelClass::NonFinite; }

glm::dvec2 toTexels(const LightSpace& light, const glm::dvec3& p) {
    const glm::dvec4 clip = light.viewProjection() * glm::dvec4(p, 1.0);
    if (!(clip.w > 0.0)) return glm::dvec2(std::numeric_limits<double>::quiet_NaN());
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return (ndc * 0.5 + 0.5) * double(light.resolution);
}

}  // namespace

bool sameSurface(const SurfaceSamples& samples, std::size_t i, std::size_t j) {
    const glm::dvec3 d = samples.point[j] - samples.point[i];
    const double length = glm::length(d);
    if (!(length > 0.0)) return true;
    const double tolerance = 0.5 * length;  // within about 30 degrees of each other's tangent plane
    return std::abs(glm::dot(samples.normal[i], d)) <= tolerance &&
           std::abs(glm::dot(samples.normal[j], d)) <= tolerance;
}

ShadowBoundary::ShadowBoundary(const SurfaceSamples& samples, const std::vector<PixelClass>& classes,
                               const LightSpace& light) {
    const std::size_t count = samples.size();
    texel_.assign(count, glm::dvec2(std::numeric_limits<double>::quiet_NaN()));
    onBoundary_.assign(count, 0);
    distance_.assign(count, -1.0f);
    for (std::size_t i = 0; i < count; ++i)
        if (hasVisibility(classes[i])) texel_[i] = toTexels(light, samples.point[i]);

    std::vector<glm::dvec2> points;
    const std::size_t w = std::size_t(samples.width);
    auto consider = [&](std::size_t i, std::size_t j) {
        if (!hasVisibility(classes[i]) || !hasVisibility(classes[j])) return;
        if (visibleLight(classes[i]) == visibleLight(classes[j])) return;
        if (!sameSurface(samples, i, j)) return;
        const glm::dvec2 mid = 0.5 * (texel_[i] + texel_[j]);
        if (!std::isfinite(mid.x) || !std::isfinite(mid.y)) return;
        points.push_back(mid);
        onBoundary_[visibleLight(classes[i]) ? i : j] = 1;
    };
    for (int y = 0; y < samples.height; ++y)
        for (int x = 0; x < samples.width; ++x) {
            const std::size_t i = std::size_t(y) * w + std::size_t(x);
            if (x + 1 < samples.width) consider(i, i + 1);
            if (y + 1 < samples.height) consider(i, i + w);
        }
    tree_ = PointTree(std::move(points));
}

double ShadowBoundary::distance(std::size_t i) {
    if (distance_[i] >= 0.0f) return distance_[i];
    const glm::dvec2& t = texel_[i];
    const double d = std::isfinite(t.x) && std::isfinite(t.y) ? tree_.nearestDistance(t)
                                                              : std::numeric_limits<double>::infinity();
    distance_[i] = float(d);
    return d;
}

}  // namespace shadowlab
