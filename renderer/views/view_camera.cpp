#include "views/view_camera.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <initializer_list>

namespace shadowlab {

double ViewCamera::depthOf(const glm::dvec3& p) const { return glm::dot(p - eye, forward); }

bool ViewCamera::finite() const {
    for (const glm::dvec3* v : {&eye, &forward, &right, &up})
        if (!std::isfinite(v->x) || !std::isfinite(v->y) || !std::isfinite(v->z)) return false;
    return std::isfinite(tanHalfFovY) && tanHalfFovY > 0.0 && std::isfinite(aspect) && aspect > 0.0 &&
           std::isfinite(nearPlane) && nearPlane > 0.0 && std::isfinite(farPlane) && farPlane > nearPlane;
}

}  // namespace shadowlab
