#include "editor/light_angles.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab::editor {

LightAngles anglesFromDirection(const glm::vec3& direction) {
    const glm::vec3 toLight = -glm::normalize(direction);
    LightAngles a;
    a.elevationDeg = glm::degrees(std::asin(std::clamp(toLight.y, -1.0f, 1.0f)));
    // Straight up or down has no azimuth; 0 keeps the sliders steady there.
    const float horizontal = std::hypot(toLight.x, toLight.z);
    a.azimuthDeg = horizontal > 1e-6f ? glm::degrees(std::atan2(toLight.z, toLight.x)) : 0.0f;
    return a;
}

glm::vec3 directionFromAngles(const LightAngles& angles) {
    const float az = glm::radians(angles.azimuthDeg);
    const float el = glm::radians(angles.elevationDeg);
    const glm::vec3 toLight{std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az)};
    return -toLight;
}

}  // namespace shadowlab::editor
