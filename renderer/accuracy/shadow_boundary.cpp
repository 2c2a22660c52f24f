#include "accuracy/shadow_boundary.h"

#include "reference/parallel_rows.h"
#include "views/view_select.h"

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

// Point light: d = p - light position; cubeFaceOf(d) is the face that sees it. d's texels on the plane of face f (its two other axes over its depth; NaN behind the face or more than 63 degrees off its axis).
constexpr double kFaceExtent = 2.0;  // |tan| on a face's plane: 1 = the face's edge, 2 = 63 degrees

glm::dvec2 faceTexels(const glm::dvec3& d, int face, int resolution) {
    const int axis = face / 2;
    const double depth = (face % 2 ? -1.0 : 1.0) * d[axis];
    const glm::dvec2 onPlane(d[(axis + 1) % 3] / depth, d[(axis + 2) % 3] / depth);
    if (!(depth > 0.0) || std::abs(onPlane.x) > kFaceExtent || std::abs(onPlane.y) > kFaceExtent)
        return glm::dvec2(std::numeric_limits<double>::quiet_NaN());
    return (onPlane * 0.5 + 0.5) * double(resolution);
}

bool finite2(const glm::dvec2& t) { return std::isfinite(t.x) && std::isfinite(t.y); }

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
                               const LightSpace& light, const BoundaryProbe& probe,
                               const std::vector<ShadowView>& cascades)
    : samples_(&samples), classes_(&classes), light_(light), probe_(probe), cascades_(cascades) {
    // Rows of the light's view rotation: its image axes in world space.
    right_ = glm::dvec3(light.view[0][0], light.view[1][0], light.view[2][0]);
    up_ = glm::dvec3(light.view[0][1], light.view[1][1], light.view[2][1]);

    // Each row's pixels with visibility are counted, then numbered in pixel order (slot_), and their state is set
    // by the rows below, on every core (PixelVector: no serial initialization first).
    const std::size_t count = samples.size();
    const std::size_t w = std::size_t(samples.width);
    const std::size_t rowCount = std::size_t(std::max(samples.height, 0));
    std::vector<std::size_t> rowStart(rowCount + 1, 0);
    parallelRows(samples.height, [&](int row) {
        std::size_t n = 0;
        for (std::size_t i = std::size_t(row) * w; i < std::size_t(row + 1) * w; ++i) n += hasVisibility(classes[i]);
        rowStart[std::size_t(row) + 1] = n;
    });
    for (std::size_t row = 0; row < rowCount; ++row) rowStart[row + 1] += rowStart[row];
    const std::size_t slots = rowStart[rowCount];
    slot_.resize(count);
    texel_.resize(slots);
    onBoundary_.resize(slots);
    visibleDistance_.resize(slots);
    probedTo_.resize(slots);
    flipAt_.resize(slots);
    point_ = probe.light.type == LightType::Point;
    if (point_) face_.resize(slots);
    if (!cascades_.empty()) texelScale_.resize(slots);
    parallelRows(samples.height, [&](int row) {
        std::size_t s = rowStart[std::size_t(row)];
        for (std::size_t i = std::size_t(row) * w; i < std::size_t(row + 1) * w; ++i) {
            if (!hasVisibility(classes[i])) {
                slot_[i] = -1;
                continue;
            }
            slot_[i] = std::int32_t(s);
            onBoundary_[s] = 0;
            visibleDistance_[s] = -1.0f;  // not yet computed
            probedTo_[s] = 0.0f;
            flipAt_[s] = std::numeric_limits<float>::infinity();
            if (point_) {
                const glm::dvec3 d = samples.point[i] - probe.light.position;
                face_[s] = std::uint8_t(cubeFaceOf(d));  // the face the lookup selects
                texel_[s] = faceTexels(d, face_[s], light.resolution);
            } else {
                texel_[s] = toTexels(light, samples.point[i]);
            }
            // Beyond the shadow distance no cascade holds a pixel: the last one's texels measure it.
            if (!cascades_.empty()) texelScale_[s] = float(light.texelWorldSize / texelWorldSizeAt(samples.point[i]));
            ++s;
        }
    });

    // The boundary points of each row's pairs (the pixel and its right and lower neighbours) on all cores, joined in
    // row order; the lit pixel of each pair is marked after, as a pair may mark a pixel of the next row.
    struct RowBoundary {
        std::vector<glm::dvec2> points;
        std::array<std::vector<glm::dvec2>, 6> facePoints;
        std::vector<std::size_t> marked;
    };
    std::vector<RowBoundary> rows(std::size_t(std::max(samples.height, 0)));
    parallelRows(samples.height, [&](int y) {
        RowBoundary& out = rows[std::size_t(y)];
        auto consider = [&](std::size_t i, std::size_t j) {
            if (!hasVisibility(classes[i]) || !hasVisibility(classes[j])) return;
            if (isLit(classes[i]) == isLit(classes[j])) return;
            if (!sameSurface(samples, i, j)) return;
            bool kept = false;
            if (point_) {
                for (int f = 0; f < 6; ++f) {
                    const glm::dvec2 a = faceTexels(samples.point[i] - probe.light.position, f, light.resolution);
                    const glm::dvec2 b = faceTexels(samples.point[j] - probe.light.position, f, light.resolution);
                    if (!finite2(a) || !finite2(b)) continue;
                    out.facePoints[std::size_t(f)].push_back(0.5 * (a + b));
                    kept = true;
                }
            } else {
                const glm::dvec2 mid = 0.5 * (texel_[std::size_t(slot_[i])] + texel_[std::size_t(slot_[j])]);
                if (!finite2(mid)) return;
                out.points.push_back(mid);
                kept = true;
            }
            if (kept) out.marked.push_back(isLit(classes[i]) ? i : j);
        };
        for (int x = 0; x < samples.width; ++x) {
            const std::size_t i = std::size_t(y) * w + std::size_t(x);
            if (x + 1 < samples.width) consider(i, i + 1);
            if (y + 1 < samples.height) consider(i, i + w);
        }
    });
    std::vector<glm::dvec2> points;
    std::array<std::vector<glm::dvec2>, 6> facePoints;
    for (const RowBoundary& row : rows) {
        points.insert(points.end(), row.points.begin(), row.points.end());
        for (std::size_t f = 0; f < 6; ++f)
            facePoints[f].insert(facePoints[f].end(), row.facePoints[f].begin(), row.facePoints[f].end());
        for (std::size_t i : row.marked) onBoundary_[std::size_t(slot_[i])] = 1;
    }
    tree_ = PointTree(std::move(points));
    for (std::size_t f = 0; f < 6; ++f) faceTrees_[f] = PointTree(std::move(facePoints[f]));
}

std::size_t ShadowBoundary::pointCount() const {
    std::size_t n = tree_.size();
    for (const PointTree& t : faceTrees_) n += t.size();
    return n;
}

double ShadowBoundary::texelWorldSizeAt(const glm::dvec3& p) const {
    if (point_) {
        const glm::dvec3 d = glm::abs(p - probe_.light.position);
        // A 90-degree face: 2 x depth across, over the map's resolution.
        return 2.0 * std::max({d.x, d.y, d.z, light_.nearPlane}) / double(light_.resolution);
    }
    if (!cascades_.empty()) {
        const ShadowView* holding = viewHolding(cascades_, p);
        return (holding ? holding : &cascades_.back())->space.texelWorldSize;
    }
    return light_.perspective ? light_.texelSizeAt(glm::dot(p - light_.position, light_.direction))
                              : light_.texelWorldSize;
}

glm::dvec3 ShadowBoundary::alongLight(const glm::dvec3& p) const {
    return probe_.light.positional() ? glm::normalize(p - probe_.light.position) : light_.direction;
}

bool ShadowBoundary::alongTheRays(std::size_t i) const {
    return std::abs(glm::dot(samples_->normal[i], alongLight(samples_->point[i]))) < 1e-9;
}

double ShadowBoundary::probe(std::size_t i, double k) {
    const std::size_t s = std::size_t(slot_[i]);  // distance() asks only pixels with visibility
    if (flipAt_[s] <= k) return flipAt_[s];
    if (!probe_.bvh || probedTo_[s] >= k) return kInfinity;
    const glm::dvec3& p = samples_->point[i];
    const glm::dvec3& n = samples_->normal[i];
    const bool lit = isLit((*classes_)[i]);
    // Moving along the light's rays keeps the texel: lift each ring point back onto the tangent plane that way.
    if (alongTheRays(i)) return kInfinity;
    const glm::dvec3 along = alongLight(p);
    const double nDotAlong = glm::dot(n, along);
    const double texelWorld = texelWorldSizeAt(p);
    // The ring lies on the light's image plane: a point light's is the plane of the pixel's cube face.
    glm::dvec3 right = right_, up = up_;
    if (point_) {
        const int axis = face_[s] / 2;
        right = glm::dvec3(0.0);
        up = glm::dvec3(0.0);
        right[(axis + 1) % 3] = 1.0;
        up[(axis + 2) % 3] = 1.0;
    }
    if (probedTo_[s] == 0.0f) ++probedPixels_;
    std::size_t rays = 0;
    double radius = double(probedTo_[s]);
    double found = kInfinity;
    while (radius < k && found == kInfinity) {
        radius = std::min(radius + kProbeStepTexels, k);
        for (int d = 0; d < kProbeDirections; ++d) {
            const double angle = 2.0 * std::numbers::pi * (double(d) + 0.5 * double(int(radius / kProbeStepTexels) % 2)) /
                                 kProbeDirections;
            const glm::dvec3 offset = (std::cos(angle) * right + std::sin(angle) * up) * (radius * texelWorld);
            const glm::dvec3 q = p + offset - along * (glm::dot(n, offset) / nDotAlong);
            ++rays;
            if (litAt(*probe_.bvh, probe_.light, q, n, probe_.sceneRadius) != lit) {
                found = radius;
                break;
            }
        }
    }
    probeRays_ += rays;
    probedTo_[s] = float(radius);
    flipAt_[s] = float(found);
    return found;
}

double ShadowBoundary::visibleDistance(std::size_t i) {
    if (slot_[i] < 0) return kInfinity;  // no surface the light reaches: on no side of a boundary
    const std::size_t s = std::size_t(slot_[i]);
    if (visibleDistance_[s] < 0.0f) {
        const glm::dvec2& t = texel_[s];
        const PointTree& tree = point_ ? faceTrees_[face_[s]] : tree_;
        const double scale = texelScale_.empty() ? 1.0 : double(texelScale_[s]);
        visibleDistance_[s] = finite2(t) ? float(tree.nearestDistance(t) * scale) : float(kInfinity);
    }
    return visibleDistance_[s];
}

double ShadowBoundary::distance(std::size_t i, double k) {
    const double visible = visibleDistance(i);
    if (visible <= k || slot_[i] < 0) return visible;
    return std::min(visible, probe(i, k));
}

void ShadowBoundary::prepareVisible() {
    const std::size_t count = classes_ ? classes_->size() : 0;
    const int rows = int((count + 255) / 256);
    parallelRows(rows, [&](int row) {
        const std::size_t end = std::min(count, std::size_t(row + 1) * 256);
        for (std::size_t i = std::size_t(row) * 256; i < end; ++i)
            if (hasVisibility((*classes_)[i])) visibleDistance(i);
    });
}

DistanceState ShadowBoundary::state(std::size_t i, double k) const {
    const std::int32_t slot = slot_[i];
    DistanceState s = slot >= 0 ? DistanceState{visibleDistance_[std::size_t(slot)], flipAt_[std::size_t(slot)],
                                                probedTo_[std::size_t(slot)]}
                                : DistanceState{-1.0f, float(kInfinity), 0.0f};
    if (s.visible < 0.0f) s.visible = float(kInfinity);  // not computed: no surface here
    // distance(i, k) answers "farther than k" without probing when the tangent plane runs along the light's rays.
    if (s.visible > k && s.flipAt > k && s.probedTo < k && probes()) {
        if (alongTheRays(i)) s.probedTo = float(k);
    }
    return s;
}

void ShadowBoundary::prepare(const std::vector<std::size_t>& pixels, double k) {
    const int rows = int((pixels.size() + 63) / 64);
    parallelRows(rows, [&](int row) {
        const std::size_t end = std::min(pixels.size(), std::size_t(row + 1) * 64);
        for (std::size_t j = std::size_t(row) * 64; j < end; ++j) distance(pixels[j], k);
    });
}

}  // namespace shadowlab
