#pragma once
// Whether two view volumes (a light's view and the camera's) can share a point: the shadow planner skips a view
// whose volume misses everything the camera sees. Conservative: "overlap" may be said of volumes that do not touch
// (a separating plane is searched among the two volumes' faces only), never the other way round.
#include <glm/ext/matrix_double4x4.hpp>

namespace shadowlab {

// Volumes as clip-from-world matrices (x, y, z within [-w, w]); both in the same world (render-origin-relative).
bool volumesOverlap(const glm::dmat4& a, const glm::dmat4& b);

}  // namespace shadowlab
