#pragma once
// The world point under a pixel of the last frame: its depth read back from the view's depth buffer and unprojected
// with the frame's camera. One pixel's read: cheaper than a BVH of the scene, and it finds exactly the surface shown.
#include "frame/frame_stats.h"
#include "frame/render_target.h"

#include <glm/ext/vector_double3.hpp>

#include <optional>

namespace shadowlab {

// The surface at pixel (x, y) (y = 0 at the top, as a window counts) of the frame `stats` describes, drawn into
// `target`; nullopt when the pixel shows no surface (background) or lies outside the view.
std::optional<glm::dvec3> pickSurface(const RenderTarget& target, const FrameStats& stats, int x, int y);

// The world point at window depth `depth` (0..1) under the centre of pixel (x, y) (top-down) of a width x height view.
glm::dvec3 unprojectPixel(const FrameStats& stats, int x, int y, int width, int height, double depth);

}  // namespace shadowlab
