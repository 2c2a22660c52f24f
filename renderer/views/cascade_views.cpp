// Cascaded shadow maps: the fit mode `cascades` (projection.fit). Each cascade is an orthographic view along the
// light, fitted to its slice of the camera's frustum: stable (the slice's bounding sphere, its size rounded and its
// centre snapped to whole texels, so camera translation and rotation move no texel edge) or tight (the slice's box in
// light space). Depth always spans the scene's bounding sphere along the light: casters between the light and a
// slice still cast (with depth clamp, as the scene fit), and the depth bias means the same in every cascade.
#include "views/cascade_views.h"

#include "views/depth_bounds.h"
#include "views/view_builders.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace shadowlab {

std::array<glm::dvec3, 8> sliceCorners(const ViewCamera& c, double a, double b) {
    std::array<glm::dvec3, 8> corners;
    const double ty = c.tanHalfFovY, tx = ty * c.aspect;
    int k = 0;
    for (double z : {a, b})
        for (double sx : {-1.0, 1.0})
            for (double sy : {-1.0, 1.0}) corners[std::size_t(k++)] = c.eye + c.forward * z + c.right * (sx * tx * z) + c.up * (sy * ty * z);
    return corners;
}

namespace {

// The smallest sphere holding the slice [a, b]: its centre lies on the view axis where the near and far corners are
// equally far, or at the far face's centre when the far corners alone decide. Depends only on a, b, the field of view
// and the aspect, never on where the camera is or looks: the stable fit's size does not change as it moves.
void sliceSphere(const ViewCamera& c, double a, double b, double& centreDepth, double& radius) {
    const double k2 = c.tanHalfFovY * c.tanHalfFovY * (1.0 + c.aspect * c.aspect);  // corner offset^2 per depth^2
    centreDepth = std::min(0.5 * (a + b) * (1.0 + k2), b);
    // In units of b: squared depths below 1e-154 underflow to 0 (a near plane of 1e-300, HARD_CASES 18).
    const double ca = (centreDepth - a) / b, an = a / b, bc = (b - centreDepth) / b;
    radius = b * std::sqrt(std::max(ca * ca + an * an * k2, bc * bc + k2));
}

// Rounded up to 1/64 of its power of two: the same size from the same inputs, whatever rounding the sphere had.
double roundedUp(double size) {
    const double step = std::ldexp(1.0, std::ilogb(size) - 6);
    return std::ceil(size / step) * step;
}

}  // namespace

double cascadeShadowDistance(const ProjectionSettings& projection, const ViewCamera& camera) {
    return projection.shadowDistance > 0.0f ? double(projection.shadowDistance) : camera.farPlane;
}

ViewDepths boundsDepthRange(const Bounds& bounds, const glm::dvec3& origin, const ViewCamera& camera) {
    if (bounds.empty) return {};
    ViewDepths r{std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 corner(c & 1 ? bounds.max.x : bounds.min.x, c & 2 ? bounds.max.y : bounds.min.y,
                                c & 4 ? bounds.max.z : bounds.min.z);
        const double depth = camera.depthOf(corner - origin);
        r.nearest = std::min(r.nearest, depth);
        r.farthest = std::max(r.farthest, depth);
    }
    r.nearest = std::max(r.nearest, camera.nearPlane);
    return r;
}

std::vector<double> cascadeFarDepths(const ProjectionSettings& projection, const ViewCamera& camera,
                                     std::string& why, const ViewDepths* scene) {
    const int count = std::clamp(projection.cascadeCount, 1, 4);
    const bool manual = projection.splits.x > 0.0f;
    double n = camera.nearPlane, f = cascadeShadowDistance(projection, camera);
    if (scene && scene->farthest > n && f > n) {
        // Only the depths the scene covers: the practical scheme's first split then lands where things are. A scene
        // beyond the shadow distance or without depth (a quad facing the camera) leaves no range: the camera's stays.
        const double tightNear = manual ? n : std::min(std::max(n, scene->nearest), f);
        const double tightFar = std::min(f, scene->farthest);
        if (tightFar > tightNear) {
            n = tightNear;
            f = tightFar;
        }
    }
    if (!(f > n)) {
        why = "projection.shadowDistance: " + std::to_string(f) + " is not beyond the camera's near plane (" +
              std::to_string(n) + ")";
        return {};
    }
    std::vector<double> far(std::size_t(count), f);
    for (int i = 0; i + 1 < count; ++i) {
        if (manual) {
            const double split = double(projection.splits[i]);
            if (!(split > (i == 0 ? n : far[std::size_t(i - 1)])) || !(split < f)) {
                why = "projection.splits: split " + std::to_string(i) + " (" + std::to_string(split) +
                      ") must lie beyond the one before it (or the camera's near plane " + std::to_string(n) +
                      ") and before the shadow distance (" + std::to_string(f) + ")";
                return {};
            }
            far[std::size_t(i)] = split;
        } else {
            // The logarithmic term starts no nearer than f x float's epsilon: the GPU cannot tell nearer depths
            // from the camera's (positions are floats), and a glTF camera's znear may be any positive double, so
            // f / n would overflow (1e-307) and the first cascade would be too small for a float matrix.
            const double t = double(i + 1) / count, lambda = double(projection.splitLambda);
            const double logNear = std::max(n, f * double(std::numeric_limits<float>::epsilon()));
            far[std::size_t(i)] = lambda * logNear * std::pow(f / logNear, t) + (1.0 - lambda) * (n + (f - n) * t);
        }
    }
    // Practical splits of a range a few ulps wide round onto each other (or onto n): a zero-width slice holds
    // nothing and its blend band would divide by zero. It is merged into the next one (fewer cascades).
    std::vector<double> merged;
    for (double depth : far)
        if (depth > (merged.empty() ? n : merged.back())) merged.push_back(depth);
    return merged;
}

std::vector<CascadeSlice> cascadeSlices(const ProjectionSettings& projection, const ViewCamera& camera,
                                        std::string& why, const ViewDepths* scene) {
    const std::vector<double> far = cascadeFarDepths(projection, camera, why, scene);
    std::vector<CascadeSlice> slices;
    const double band = std::clamp(double(projection.blendBand), 0.0, 0.5);
    for (std::size_t i = 0; i < far.size(); ++i) {
        CascadeSlice s;
        s.camera = camera;
        s.nearDepth = i == 0 ? camera.nearPlane : far[i - 1];
        // The first cascade's volume starts where the scene does (nothing nearer casts onto a visible receiver).
        s.fitNear = i == 0 ? (scene && !(projection.splits.x > 0.0f) ? std::clamp(scene->nearest, camera.nearPlane, far[0])
                                                             : camera.nearPlane)
                           : slices.back().blendStart;
        s.farDepth = far[i];
        // The last cascade has no next one to fade into: it ends at the shadow distance.
        s.blendStart = i + 1 < far.size() ? s.farDepth - band * (s.farDepth - s.nearDepth) : s.farDepth;
        slices.push_back(s);
    }
    return slices;
}

bool cascadesApply(const LightSettings& light) {
    return light.type == LightType::Directional && light.projection.fit == ProjectionFit::Cascades;
}

std::vector<ShadowView> buildCascadeViews(const ViewBuildInput& in, std::string& why) {
    if (!in.camera) {
        why = "projection.fit: cascades follow a camera, and this use has none (use fit scene here)";
        return {};
    }
    if (!in.camera->finite()) {
        why = "projection.fit: cascades cannot follow a camera whose position, direction or planes are not finite";
        return {};
    }
    const glm::dvec3 dir(in.light.direction);
    const double dirLength = glm::length(dir);
    if (!std::isfinite(dirLength) || dirLength < 1e-12) {
        why = "light.direction: must be finite and non-zero";
        return {};
    }
    const glm::dvec3 direction = dir / dirLength;
    const bool stable = in.light.projection.cascadeFit == CascadeFit::Stable;
    // The tight fit also tightens the splits to the depths the scene covers from here; the stable fit keeps splits
    // that depend on nothing but the camera's planes and the keys, or its cascades' sizes would change as it moves.
    // The depth-bounds fit (either kind) spans the depths the camera sees, quantized so that the stable fit's sizes
    // change only when what is seen moves by a grid step; manual splits are the user's and are kept.
    const ViewDepths sceneDepths = boundsDepthRange(in.bounds, in.origin, *in.camera);
    const std::optional<ViewDepths> seen = cascadeDepthBounds(in.light, *in.camera);
    const ViewDepths* spanned = seen ? &*seen : stable || in.bounds.empty ? nullptr : &sceneDepths;
    const std::vector<CascadeSlice> slices = cascadeSlices(in.light.projection, *in.camera, why, spanned);
    if (slices.empty()) return {};

    const glm::dmat3 basis = lightBasis(direction);  // right, up, back
    const glm::dvec3 sceneCentre = in.bounds.centreOrOrigin() - in.origin;
    const double sceneRadius = in.bounds.empty ? 1.0 : std::max(double(in.bounds.radius()), 1e-3);
    const double depthRadius = sceneRadius + std::max(sceneRadius * 0.02, 1e-3);
    const int resolution = std::max(in.light.shadow.resolution, 1);

    std::vector<ShadowView> views;
    for (std::size_t i = 0; i < slices.size(); ++i) {
        const CascadeSlice& slice = slices[i];
        double halfSize = 0.0, cx = 0.0, cy = 0.0;
        if (stable) {
            double centreDepth = 0.0, radius = 0.0;
            sliceSphere(*in.camera, slice.fitNear, slice.farDepth, centreDepth, radius);
            halfSize = roundedUp(radius);
            const glm::dvec3 centre = in.camera->eye + in.camera->forward * centreDepth;
            // Snapped to whole texels of the light's fixed grid (relative to the render origin, fixed per scene).
            const double texel = 2.0 * halfSize / resolution;
            cx = std::round(glm::dot(centre, basis[0]) / texel) * texel;
            cy = std::round(glm::dot(centre, basis[1]) / texel) * texel;
        } else {
            double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
            double hi[2] = {-lo[0], -lo[1]};
            for (const glm::dvec3& p : sliceCorners(*in.camera, slice.fitNear, slice.farDepth))
                for (int a = 0; a < 2; ++a) {
                    lo[a] = std::min(lo[a], glm::dot(p, basis[a]));
                    hi[a] = std::max(hi[a], glm::dot(p, basis[a]));
                }
            cx = 0.5 * (lo[0] + hi[0]);
            cy = 0.5 * (lo[1] + hi[1]);
            halfSize = 0.5 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
        }
        // The eye on the light's side of the scene's bounding sphere, on the cascade's axis.
        const glm::dvec3 eye = basis[0] * cx + basis[1] * cy + basis[2] * (glm::dot(sceneCentre, basis[2]) + depthRadius);
        LightSpace space = orthoLightSpace(in.light, direction, eye, halfSize, 0.0, 2.0 * depthRadius);
        // A stable cascade's eye in light-view coordinates exactly (cx, cy, the depth), not -dot(basis, eye)
        // rounded: as the camera moves, the depth terms stay the same numbers and x, y move by whole texels, so a
        // moved cascade's texels are its old ones moved (the scrolling cache, views/cascade_scroll.h).
        if (stable)
            space.view[3] = glm::dvec4(-cx, -cy, -(glm::dot(sceneCentre, basis[2]) + depthRadius), 1.0);
        if (!allFinite(space.view) || !allFinite(space.projection) || !(halfSize > 0.0)) {
            why = "projection.fit: cascade " + std::to_string(i) + "'s matrices are not finite (check the camera, the "
                  "splits and the shadow distance)";
            return {};
        }
        views.push_back({in.lightIndex, ShadowViewKind::Cascade, int(i), space, slice});
    }
    return views;
}

}  // namespace shadowlab
