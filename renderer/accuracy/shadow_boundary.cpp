#include "accuracy/shadow_boundary.h"

#include "reference/parallel_rows.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace shadowlab {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kProbeDirections = 16;
constexpr double kProbeStepTexels = 0.5;

// Out of range: the light does not reach it, so it is on neither side of a shadow boundary.
bool hasVisibility(PixelClass c) {
    return c != PixelClass::Background && c != PixelClass::NonFinite && c != PixelClass::OutOfRange;
}

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
                               const LightSpace& light, const BoundaryProbe& probe)
    : samples_(&samples), classes_(&classes), light_(light), probe_(probe) {
    // Rows of the light's view rotation: its image axes in world space.
    right_ = glm::dvec3(light.view[0][0], light.view[1][0], light.view[2][0]);
    up_ = glm::dvec3(light.view[0][1], light.view[1][1], light.view[2][1]);

    const std::size_t count = samples.size();
    texel_.assign(count, glm::dvec2(std::numeric_limits<double>::quiet_NaN()));
    onBoundary_.assign(count, 0);
    visibleDistance_.assign(count, -1.0f);
    probedTo_.assign(count, 0.0f);
    flipAt_.assign(count, std::numeric_limits<float>::infinity());
    for (std::size_t i = 0; i < count; ++i)
        if (hasVisibility(classes[i])) texel_[i] = toTexels(light, samples.point[i]);

    std::vector<glm::dvec2> points;
    const std::size_t w = std::size_t(samples.width);
    auto consider = [&](std::size_t i, std::size_t j) {
        if (!hasVisibility(classes[i]) || !hasVisibility(classes[j])) return;
        if (isLit(classes[i]) == isLit(classes[j])) return;
        if (!sameSurface(samples, i, j)) return;
        const glm::dvec2 mid = 0.5 * (texel_[i] + texel_[j]);
        if (!std::isfinite(mid.x) || !std::isfinite(mid.y)) return;
        points.push_back(mid);
        onBoundary_[isLit(classes[i]) ? i : j] = 1;
    };
    for (int y = 0; y < samples.height; ++y)
        for (int x = 0; x < samples.width; ++x) {
            const std::size_t i = std::size_t(y) * w + std::size_t(x);
            if (x + 1 < samples.width) consider(i, i + 1);
            if (y + 1 < samples.height) consider(i, i + w);
        }
    tree_ = PointTree(std::move(points));
}

double ShadowBoundary::probe(std::size_t i, double k) {
    if (flipAt_[i] <= k) return flipAt_[i];
    if (!probe_.bvh || probedTo_[i] >= k) return kInfinity;
    const glm::dvec3& p = samples_->point[i];
    const glm::dvec3& n = samples_->normal[i];
    const bool lit = isLit((*classes_)[i]);
    // Moving along the light's rays keeps the texel: lift each ring point back onto the tangent plane that way.
    const glm::dvec3 along = probe_.light.positional() ? glm::normalize(p - probe_.light.position) : light_.direction;
    const double nDotAlong = glm::dot(n, along);
    if (std::abs(nDotAlong) < 1e-9) return kInfinity;
    const double texelWorld =
        light_.perspective ? light_.texelSizeAt(glm::dot(p - light_.position, light_.direction)) : light_.texelWorldSize;
    if (probedTo_[i] == 0.0f) ++probedPixels_;
    std::size_t rays = 0;
    double radius = double(probedTo_[i]);
    double found = kInfinity;
    while (radius < k && found == kInfinity) {
        radius = std::min(radius + kProbeStepTexels, k);
        for (int d = 0; d < kProbeDirections; ++d) {
            const double angle = 2.0 * std::numbers::pi * (double(d) + 0.5 * double(int(radius / kProbeStepTexels) % 2)) /
                                 kProbeDirections;
            const glm::dvec3 offset = (std::cos(angle) * right_ + std::sin(angle) * up_) * (radius * texelWorld);
            const glm::dvec3 q = p + offset - along * (glm::dot(n, offset) / nDotAlong);
            ++rays;
            if (litAt(*probe_.bvh, probe_.light, q, n, probe_.sceneRadius) != lit) {
                found = radius;
                break;
            }
        }
    }
    probeRays_ += rays;
    probedTo_[i] = float(radius);
    flipAt_[i] = float(found);
    return found;
}

double ShadowBoundary::visibleDistance(std::size_t i) {
    if (visibleDistance_[i] < 0.0f) {
        const glm::dvec2& t = texel_[i];
        visibleDistance_[i] =
            std::isfinite(t.x) && std::isfinite(t.y) ? float(tree_.nearestDistance(t)) : float(kInfinity);
    }
    return visibleDistance_[i];
}

double ShadowBoundary::distance(std::size_t i, double k) {
    const double visible = visibleDistance(i);
    if (visible <= k) return visible;
    return std::min(visible, probe(i, k));
}

void ShadowBoundary::prepare(const std::vector<std::size_t>& pixels, double k) {
    const int rows = int((pixels.size() + 63) / 64);
    parallelRows(rows, [&](int row) {
        const std::size_t end = std::min(pixels.size(), std::size_t(row + 1) * 64);
        for (std::size_t j = std::size_t(row) * 64; j < end; ++j) distance(pixels[j], k);
    });
}

}  // namespace shadowlab
