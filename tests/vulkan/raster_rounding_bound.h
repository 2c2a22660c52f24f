#pragma once
// How far two conforming rasterizers may put one texel's depth apart when both draw the same triangles with the same
// depth bias, derived from the geometry (not a tolerance picked to pass): each snaps a vertex to its subpixel grid
// (1/2^subPixelBits of a texel) and may land one grid step away from the other in x and in y. That moves the
// triangle's depth plane, so
//   - the plane's depth at the texel centre moves: |dg| |c - p| + |g'| |dp| (g the plane's depth gradient per texel,
//     p the vertex nearest the centre, dp <= sqrt(2) grid steps);
//   - the slope-scaled bias moves: slope factor x |dg|, where the gradient's change is bounded through the edge matrix
//     E = [p1 - p0, p2 - p0] (g = E^-T dz): |dg| <= |g| k / (1 - k), k = ||E^-1|| ||dE||, ||dE|| <= 4 grid steps (each
//     edge's two ends apart by up to a grid step in x and y). A sliver (small ||E||^-1) magnifies the rounding: that
//     is the term a constant tolerance cannot state. Where k >= 1/2 the slope is not determined by the snapped
//     vertices at all: a depth the triangle interpolates lies between its corners' depths, and its bias between the
//     constant term and the clamp; with a slope factor and no clamp such texels have no bound (counted, never
//     silently passed);
//   - each vertex's depth may round one float step apart in each (dz <= 2 steps at the triangle's largest depth):
//     the plane moves by dz at the vertex, and the gradient by ||E^-1|| 2 sqrt(2) dz (times the slope factor).
// The texel's triangle is the one whose biased depth at the centre (its plane plus the polygon offset the snippet
// states) is nearest the GL map's value among those covering the centre (or passing within two grid steps of it:
// either rasterizer may take an edge texel).
#include "vulkan_depth_pass.h"

#include <vector>

namespace shadowlab::test {

struct RoundingBound {
    std::vector<double> depth;  // per texel (GL order): the bound on |vk - gl| beyond the format's one step;
                                // < 0: no bound (a triangle thinner than the grid covers it, or none does)
    long undetermined = 0;      // written texels without a bound: their triangle's slope is not determined by the
                                // grid (k >= 1/2), the slope factor is not 0 and no clamp limits the bias
    long uncovered = 0;         // written texels no triangle covers (on this CPU model)
};

// `glMap`: ShadowLab's map of the same pass, which picks each texel's triangle. The bias's slope factor is the
// parsed snippet's (input.raster), so a slope factor the export gets wrong moves the maps apart beyond the bound.
RoundingBound rasterRoundingBound(const DepthPassInput& input, const std::vector<float>& glMap, int subPixelBits);

}  // namespace shadowlab::test
