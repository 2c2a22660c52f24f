#include "reference/soft_visibility.h"

#include "reference/parallel_rows.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace shadowlab {

namespace {

// splitmix64: a well-mixed 64-bit value from any input (the jitter's only source of randomness).
std::uint64_t mix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

double unitFraction(std::uint64_t x) { return double(x >> 11) * (1.0 / 9007199254740992.0); }  // [0, 1), 53 bits

// Shirley and Chiu's concentric map: the unit square onto the unit disc, keeping strata compact and areas equal.
glm::dvec2 concentric(double u, double v) {
    const double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
    if (a == 0.0 && b == 0.0) return {0.0, 0.0};
    constexpr double quarterPi = 0.78539816339744830962;
    double r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = quarterPi * (b / a);
    } else {
        r = b;
        phi = 2.0 * quarterPi - quarterPi * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

// An orthonormal pair perpendicular to unit `axis` (Duff et al. 2017), the same for the same axis.
void basis(const glm::dvec3& axis, glm::dvec3& e1, glm::dvec3& e2) {
    const double sign = std::copysign(1.0, axis.z);
    const double a = -1.0 / (sign + axis.z);
    const double b = axis.x * axis.y * a;
    e1 = {1.0 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x};
    e2 = {b, sign + axis.y * axis.y * a, -axis.y};
}

// Rows of cells over the unit square: about sqrt(N) rows, row j holding cells floor(jN/r) .. floor((j+1)N/r) - 1.
int rowsFor(int n) { return std::max(1, int(std::lround(std::sqrt(double(n))))); }

}  // namespace

SoftLight softLight(const LightSettings& light, int rays) {
    SoftLight disc;
    disc.rays = rays;
    const double size = std::max(double(light.size), 0.0);
    disc.discRadius = light.type == LightType::Directional ? std::tan(glm::radians(size) * 0.5) : size;
    return disc;
}

double analyticPenumbraWidth(const ReferenceLight& light, const SoftLight& disc, double gap, double lightToEdge) {
    if (!light.positional()) return gap * 2.0 * disc.discRadius;
    return lightToEdge > 0.0 ? gap * 2.0 * disc.discRadius / lightToEdge : 0.0;
}

namespace {

// The first cell of row j: floor(jN/r).
int rowStart(int row, int n, int rows) { return int((std::int64_t(row) * n) / rows); }

// Sample k, in row `row` of `rows` (cells first .. first + cells - 1), jittered by `seed`.
glm::dvec2 cellPoint(int k, int row, int rows, int first, int cells, std::uint64_t seed) {
    const std::uint64_t h = mix(seed * 0x100000001B3ull + std::uint64_t(k));
    const double ju = unitFraction(h), jv = unitFraction(mix(h));
    return concentric((double(k - first) + ju) / double(cells), (double(row) + jv) / double(rows));
}

}  // namespace

glm::dvec2 stratifiedDiscPoint(int k, int n, std::uint64_t seed) {
    const int rows = rowsFor(n);
    // The row holding cell k: the last j with floor(jN/r) <= k.
    int row = int((std::int64_t(k) * rows) / n);
    while (row + 1 < rows && rowStart(row + 1, n, rows) <= k) ++row;
    while (row > 0 && rowStart(row, n, rows) > k) --row;
    const int first = rowStart(row, n, rows);
    return cellPoint(k, row, rows, first, rowStart(row + 1, n, rows) - first, seed);
}

SoftRays softRays(const ReferenceLight& light, const SoftLight& disc, const glm::dvec3& point,
                  const glm::dvec3& normal, double sceneRadius, std::uint64_t seed) {
    SoftRays rays;
    const glm::dvec3 origin = shadowRayOrigin(point, normal, sceneRadius);
    rays.origin = glm::vec3(origin);
    rays.tFar = light.positional() ? 1.0f - 1e-6f : std::numeric_limits<float>::infinity();  // a segment to the disc
    const glm::dvec3 axis = towardLight(light, point);  // the disc faces the point (directional: the light's axis)
    glm::dvec3 e1, e2;
    basis(axis, e1, e2);
    rays.directions.reserve(std::size_t(std::max(disc.rays, 0)));
    // stratifiedDiscPoint's samples in order, walking the rows instead of searching each sample's (the same row,
    // first cell and cell count: the divisions of that search cost as much as the traversal of a coherent ray).
    const int n = disc.rays, rows = rowsFor(n);
    int row = 0, first = 0, next = rowStart(1, n, rows);
    for (int k = 0; k < n; ++k) {
        while (row + 1 < rows && next <= k) {
            ++row;
            first = next;
            next = rowStart(row + 1, n, rows);
        }
        const glm::dvec2 s = cellPoint(k, row, rows, first, next - first, seed) * disc.discRadius;
        const glm::dvec3 direction =
            light.positional() ? light.position + e1 * s.x + e2 * s.y - origin : axis + e1 * s.x + e2 * s.y;
        if (!(glm::dot(normal, direction) > 0.0)) continue;  // below the receiver's own surface: blocked
        rays.directions.push_back(glm::vec3(direction));
    }
    return rays;
}

float softVisibilityAt(const EmbreeScene& bvh, const ReferenceLight& light, const SoftLight& disc,
                       const glm::dvec3& point, const glm::dvec3& normal, double sceneRadius, std::uint64_t seed,
                       SoftTracing tracing) {
    if (disc.rays <= 0) return 0.0f;
    const SoftRays rays = softRays(light, disc, point, normal, sceneRadius, seed);
    int reached = 0;
    if (tracing == SoftTracing::EachRay) {
        for (const glm::vec3& direction : rays.directions)
            reached += bvh.occluded(rays.origin, direction, rays.tFar) ? 0 : 1;
        return float(reached) / float(disc.rays);
    }
    thread_local std::vector<std::uint8_t> blocked;
    blocked.resize(rays.directions.size());
    bvh.occluded(rays.origin, rays.directions.data(), rays.directions.size(), rays.tFar, blocked.data());
    for (std::uint8_t b : blocked) reached += b ? 0 : 1;
    return float(reached) / float(disc.rays);
}

SoftVisibilityResult traceSoftVisibility(const EmbreeScene& bvh, const SurfaceSamples& samples,
                                         const std::vector<PixelClass>& classes, const ReferenceLight& light,
                                         const SoftLight& disc, double sceneRadius, const std::atomic<bool>* cancel,
                                         int threads, SoftTracing tracing) {
    const auto start = std::chrono::steady_clock::now();
    SoftVisibilityResult result;
    result.visibility.assign(samples.size(), 0.0f);
    result.threads = threads > 0 ? threads : workerCount();
    if (!disc.soft() || disc.rays < 1) {
        // A hard light: exactly the hard reference's verdicts.
        for (std::size_t i = 0; i < classes.size() && i < samples.size(); ++i)
            result.visibility[i] = isLit(classes[i]) ? 1.0f : 0.0f;
        return result;
    }
    std::atomic<std::size_t> rays{0};
    parallelRows(
        samples.height,
        [&](int row) {
            if (cancel && cancel->load()) return;
            std::size_t rowRays = 0;
            for (int x = 0; x < samples.width; ++x) {
                const std::size_t i = std::size_t(row) * std::size_t(samples.width) + std::size_t(x);
                if (classes[i] != PixelClass::Lit && classes[i] != PixelClass::Shadowed) continue;
                result.visibility[i] =
                    softVisibilityAt(bvh, light, disc, samples.point[i], samples.normal[i], sceneRadius, i, tracing);
                rowRays += std::size_t(disc.rays);
            }
            rays += rowRays;
        },
        result.threads);
    result.cancelled = cancel && cancel->load();
    result.rays = rays.load();
    result.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace shadowlab
