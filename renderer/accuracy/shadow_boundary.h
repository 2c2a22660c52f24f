#pragma once
// The true shadow boundary and each pixel's distance to it, in shadow-map texels (the texel grid of the tool's
// light space, so the distance is in "texels of p's footprint" and compares with the filter's radius).
// - Visible boundary: midpoints between 4-neighbour pixels on one continuous surface whose visibility differs.
// - Point lights: each pixel's texels are on the plane of the cube face that sees it (90-degree faces, the map's
//   resolution per face); a boundary point is kept for every face whose plane extends to it (up to 63 degrees off
//   the face's axis), so a distance across a cube seam is measured in the pixel's own face's texels. Distances do not
//   depend on how a face is oriented, only on its axis.
// - A cascaded light: every cascade shares the light's orientation, so the boundary lives in one grid (the first
//   cascade's texels) and a pixel's distance is scaled into the texels of the cascade that holds it.
// - Boundaries the view does not show (behind a fold, below pixel size): a pixel farther than k from the visible
//   boundary is probed with shadow rays from rings of points on its own tangent plane, out to k texels; the
//   distance drops to the radius where visibility flips. Both are cached per pixel.
#include "accuracy/point_tree.h"
#include "light/light_space.h"
#include "views/shadow_view.h"
#include "reference/embree_scene.h"
#include "reference/pixel_vector.h"
#include "reference/surface_samples.h"
#include "reference/visibility.h"

#include <glm/ext/vector_double2.hpp>

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

namespace shadowlab {

// Pixels i, j (neighbours) lie on one continuous surface: each lies near the other's tangent plane (a depth jump
// from an object to what is behind it does not), so a change of V between them is a shadow edge, not an occlusion.
bool sameSurface(const SurfaceSamples& samples, std::size_t i, std::size_t j);

struct BoundaryProbe {
    const EmbreeScene* bvh = nullptr;  // null: no probing (visible boundary only)
    ReferenceLight light;
    double sceneRadius = 1.0;
};

// What the boundary knows of one pixel's distance so far (texels); the GPU counter decides "> k" from it by the rule
// of ShadowBoundary::distance (gpu_accuracy_counter.h).
struct DistanceState {
    float visible = 0.0f;   // to the visible boundary (+infinity when none)
    float flipAt = 0.0f;    // smallest probed radius where visibility flips (+infinity when none found)
    float probedTo = 0.0f;  // no flip closer than this (probing enabled): distance(i, k) for k <= probedTo is known
};

class ShadowBoundary {
public:
    ShadowBoundary() = default;
    // samples and classes must outlive this object.
    // `cascades`: a cascaded light's cascades (light is then the first's space); empty otherwise.
    ShadowBoundary(const SurfaceSamples& samples, const std::vector<PixelClass>& classes, const LightSpace& light,
                   const BoundaryProbe& probe, const std::vector<ShadowView>& cascades = {});

    // Distance of pixel i to the nearest true boundary in texels, exact enough to decide "> k" (+infinity when
    // there is none). Not thread-safe for one pixel; distinct pixels may be asked from several threads.
    double distance(std::size_t i, double k);
    // Distance to the nearest boundary the view shows (no probing; +infinity when none). Same threading rule.
    double visibleDistance(std::size_t i);
    // Computes the distances of many pixels on all cores (then distance() answers from the cache).
    void prepare(const std::vector<std::size_t>& pixels, double k);

    // Computes the visible distance of every pixel with a surface, on all cores.
    void prepareVisible();
    // What distance(i, k) would answer from, for pixel i (visible distance computed). probedTo is raised to k when
    // distance(i, k) already said "farther than k" without probing (a tangent plane along the light's rays).
    DistanceState state(std::size_t i, double k) const;
    bool probes() const { return probe_.bvh != nullptr; }

    std::size_t pointCount() const;
    // World size of one shadow-map texel at p (directional: constant, a cascaded light's: the holding cascade's;
    // spot: at p's depth along the axis; point: at p's depth in its cube face).
    double texelWorldSizeAt(const glm::dvec3& p) const;
    bool onBoundary(std::size_t i) const { return !slot_.empty() && slot_[i] >= 0 && onBoundary_[slot_[i]] != 0; }
    std::size_t probedPixels() const { return probedPixels_.load(); }
    std::size_t probeRays() const { return probeRays_.load(); }

private:
    double probe(std::size_t i, double k);
    glm::dvec3 alongLight(const glm::dvec3& p) const;  // the light's ray direction at p
    bool alongTheRays(std::size_t i) const;            // pixel i's tangent plane contains the light's rays: no probing

    const SurfaceSamples* samples_ = nullptr;
    const std::vector<PixelClass>* classes_ = nullptr;
    LightSpace light_;
    BoundaryProbe probe_;
    glm::dvec3 right_{1.0, 0.0, 0.0}, up_{0.0, 1.0, 0.0};  // the light's image axes in world space
    // Only pixels with visibility (about a tenth of a typical view) hold state: slot_ maps a pixel to its index in
    // the arrays below (-1: no surface the light reaches). Dense arrays over every pixel were most of this object's
    // cost: the OS zeroing their fresh pages.
    PixelVector<std::int32_t> slot_;
    PixelVector<glm::dvec2> texel_;
    PixelVector<std::uint8_t> onBoundary_;  // the lit pixel of each boundary pair: the thin line in the overlay
    PixelVector<float> visibleDistance_;    // to the visible boundary; -1 = not yet computed
    PixelVector<float> probedTo_;           // rings probed out to this radius (texels)
    PixelVector<float> flipAt_;             // smallest probed radius where visibility flips; +inf = none yet
    std::atomic<std::size_t> probedPixels_{0};
    std::atomic<std::size_t> probeRays_{0};
    PointTree tree_;
    std::array<PointTree, 6> faceTrees_;  // point light: the boundary on each cube face's plane
    PixelVector<std::uint8_t> face_;      // point light: the face that sees each pixel (by slot)
    std::vector<ShadowView> cascades_;    // a cascaded light's cascades
    PixelVector<float> texelScale_;       // cascades: the first cascade's texel over the holding cascade's (by slot)
    bool point_ = false;
};

}  // namespace shadowlab
