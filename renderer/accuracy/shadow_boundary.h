#pragma once
// The true shadow boundary and each pixel's distance to it, in shadow-map texels (the texel grid of the tool's
// light space, so the distance is in "texels of p's footprint" and compares with the filter's radius).
// Boundary points: midpoints between 4-neighbour pixels on one continuous surface whose visibility differs.
#include "accuracy/point_tree.h"
#include "light/light_space.h"
#include "reference/surface_samples.h"
#include "reference/visibility.h"

#include <glm/ext/vector_double2.hpp>

#include <cstdint>
#include <vector>

namespace shadowlab {

// Pixels i, j (neighbours) lie on one continuous surface: each lies near the other's tangent plane (a depth jump
// from an object to what is behind it does not), so a change of V between them is a shadow edge, not an occlusion.
bool sameSurface(const SurfaceSamples& samples, std::size_t i, std::size_t j);

class ShadowBoundary {
public:
    ShadowBoundary() = default;
    ShadowBoundary(const SurfaceSamples& samples, const std::vector<PixelClass>& classes, const LightSpace& light);

    // Distance of pixel i to the nearest boundary point, in texels (cached; +infinity when there is no boundary).
    double distance(std::size_t i);
    std::size_t pointCount() const { return tree_.size(); }
    bool onBoundary(std::size_t i) const { return onBoundary_[i] != 0; }
    // Pixel i's position in the shadow map, in texels (NaN when it does not project).
    const glm::dvec2& texel(std::size_t i) const { return texel_[i]; }

private:
    std::vector<glm::dvec2> texel_;
    std::vector<std::uint8_t> onBoundary_;  // the lit pixel of each boundary pair: the thin line in the overlay
    std::vector<float> distance_;           // -1 = not yet computed
    PointTree tree_;
};

}  // namespace shadowlab
