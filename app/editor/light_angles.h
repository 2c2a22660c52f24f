#pragma once
// A light direction (the way light travels) as the azimuth and elevation of where it comes from: what the Light
// panel shows. Elevation 90 = straight down.
#include <glm/vec3.hpp>

namespace shadowlab::editor {

struct LightAngles {
    float azimuthDeg = 0.0f;    // around +y, 0 = coming from +x, 90 = from +z
    float elevationDeg = 45.0f; // above the horizon
};

LightAngles anglesFromDirection(const glm::vec3& direction);
glm::vec3 directionFromAngles(const LightAngles& angles);  // unit length

}  // namespace shadowlab::editor
