#pragma once
// A pixel's footprint on its surface, as a fragment shader's dFdxFine / dFdyFine of the interpolated position see it:
// every fragment of a 2x2 quad (helpers too) interpolates its triangle's plane, so the derivative is the difference
// between where the rays through the two pixel centres of the pixel's quad row (column) meet that plane. The moments
// lookup's mip level comes from it (shaders/shadow/moments_lookup.glsl; the probe: moment_probe.cpp).
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>

#include <optional>

namespace shadowlab {

struct PositionDerivatives {
    glm::dvec3 dx{0.0}, dy{0.0};
};

// `viewProjection`: the camera's (render-origin-relative, as the triangle); pixel (x, yFromTop) of width x height;
// nullopt when a ray runs parallel to the plane.
std::optional<PositionDerivatives> fineDerivatives(const glm::dmat4& viewProjection, int width, int height, int x,
                                                   int yFromTop, const glm::dvec3 triangle[3]);

}  // namespace shadowlab
