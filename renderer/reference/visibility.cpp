#include "reference/visibility.h"

#include "reference/parallel_rows.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace shadowlab {

ReferenceLight referenceLight(const LightSettings& settings, const glm::dvec3& origin) {
    ReferenceLight light;
    light.type = settings.type;
    const glm::dvec3 direction(settings.direction);
    const double length = glm::length(direction);
    if (length > 0.0) light.direction = direction / length;
    light.position = glm::dvec3(settings.position) - origin;
    light.cosHalfCone = std::cos(glm::radians(std::clamp(double(settings.spotConeDeg), 1.0, 170.0)) * 0.5);
    light.range = std::max(double(settings.range), 0.0);
    return light;
}

bool beyondRange(const ReferenceLight& light, const glm::dvec3& point) {
    return light.positional() && light.range > 0.0 && glm::length(point - light.position) > light.range;
}

glm::dvec3 towardLight(const ReferenceLight& light, const glm::dvec3& point) {
    if (!light.positional()) return -light.direction;
    const glm::dvec3 d = light.position - point;
    const double length = glm::length(d);
    return length > 0.0 ? d / length : glm::dvec3(0.0);
}

glm::dvec3 shadowRayOrigin(const glm::dvec3& point, const glm::dvec3& normal, double sceneRadius) {
    // Off the surface along the normal (which faces the light here), far enough for float's rounding.
    const double offset = 1e-5 * (glm::length(point) + sceneRadius);
    return point + normal * offset;
}

namespace {

// The shadow ray of a point that faces the light and lies inside the cone.
bool occludedFrom(const EmbreeScene& bvh, const ReferenceLight& light, const glm::dvec3& p, const glm::dvec3& n,
                  const glm::dvec3& l, double sceneRadius) {
    const glm::dvec3 origin = shadowRayOrigin(p, n, sceneRadius);
    glm::dvec3 direction = l;
    float tFar = std::numeric_limits<float>::infinity();
    if (light.positional()) {
        direction = light.position - origin;
        tFar = 1.0f - 1e-6f;
    }
    return bvh.occluded(glm::vec3(origin), glm::vec3(direction), tFar);
}

bool outsideCone(const ReferenceLight& light, const glm::dvec3& l) {
    return light.type == LightType::Spot && glm::dot(-l, light.direction) < light.cosHalfCone;
}

}  // namespace

bool litAt(const EmbreeScene& bvh, const ReferenceLight& light, const glm::dvec3& point, const glm::dvec3& normal,
           double sceneRadius) {
    const glm::dvec3 l = towardLight(light, point);
    if (beyondRange(light, point) || outsideCone(light, l) || !(glm::dot(normal, l) > 0.0)) return false;
    return !occludedFrom(bvh, light, point, normal, l, sceneRadius);
}

VisibilityResult traceVisibility(const EmbreeScene& bvh, const SurfaceSamples& samples, const ReferenceLight& light,
                                 double sceneRadius, const std::atomic<bool>* cancel) {
    const auto start = std::chrono::steady_clock::now();
    VisibilityResult result;
    result.classes.assign(samples.size(), PixelClass::Background);
    result.lambert.assign(samples.size(), 0.0f);
    std::atomic<std::size_t> rays{0};
    parallelRows(samples.height, [&](int row) {
        if (cancel && cancel->load()) return;
        std::size_t rowRays = 0;
        for (int x = 0; x < samples.width; ++x) {
            const std::size_t i = std::size_t(row) * std::size_t(samples.width) + std::size_t(x);
            if (!samples.isSurface(i)) continue;
            if (!samples.finite[i]) {
                result.classes[i] = PixelClass::NonFinite;
                continue;
            }
            const glm::dvec3& p = samples.point[i];
            const glm::dvec3& n = samples.normal[i];
            const glm::dvec3 l = towardLight(light, p);
            const double nDotL = glm::dot(n, l);
            result.lambert[i] = float(std::max(nDotL, 0.0));
            if (beyondRange(light, p)) {
                result.classes[i] = PixelClass::OutOfRange;
                continue;
            }
            if (outsideCone(light, l)) {
                result.classes[i] = PixelClass::OutsideCone;
                continue;
            }
            if (!(nDotL > 0.0)) {
                result.classes[i] = PixelClass::FacingAway;
                continue;
            }
            ++rowRays;
            result.classes[i] = occludedFrom(bvh, light, p, n, l, sceneRadius) ? PixelClass::Shadowed : PixelClass::Lit;
        }
        rays += rowRays;
    });
    result.cancelled = cancel && cancel->load();
    result.rays = rays.load();
    result.threads = workerCount();
    result.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace shadowlab
