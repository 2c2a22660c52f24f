#pragma once
// What the main view shows at each pixel: the rasterized surface point and its geometric normal, rebuilt in double
// precision (render-origin-relative world space), row 0 = the TOP of the view. PixelVectors: the G-buffer fills them
// on every core without a serial initialization first (pixel_vector.h).
#include "reference/pixel_vector.h"

#include <glm/ext/vector_double3.hpp>

#include <cstdint>
#include <vector>

namespace shadowlab {

struct SurfaceSamples {
    int width = 0;
    int height = 0;
    PixelVector<std::int32_t> draw;   // the draw (instance with geometry) seen; -1 = background
    PixelVector<std::int32_t> instance;  // index into Scene::instances of that draw; -1 = background
    PixelVector<std::int32_t> triangle;  // the triangle of that instance's mesh; -1 = background
    PixelVector<glm::dvec3> point;    // render-origin-relative
    PixelVector<glm::dvec3> normal;   // unit geometric normal, turned toward the camera
    PixelVector<std::uint8_t> finite; // 1 when point and normal are finite

    std::size_t size() const { return draw.size(); }
    bool isSurface(std::size_t i) const { return draw[i] >= 0; }
};

}  // namespace shadowlab
