#pragma once
// Which of a light's shadow views holds a world point: the one CPU answer, used by the probe, the true-boundary
// search, the cause classifier, the flicker measure, the tuner and the export. The main pass's selection is its
// mirror: shaders/shadow/view_select.glsl (a point light's face; the hardware's cube lookup agrees, tested).
#include "views/shadow_view.h"

#include <glm/ext/vector_double3.hpp>

#include <vector>

namespace shadowlab {

struct ViewChoice {
    int view = -1;  // index into the light's views; -1: the light has no view
};

// The cube face a direction from a point light selects: the axis of largest magnitude (ties: X, then Y, then Z), its
// sign's face (>= 0: positive), in GL order +X,-X,+Y,-Y,+Z,-Z.
int cubeFaceOf(const glm::dvec3& fromLight);

// The view of `lightViews` (one light's views, as buildLightViews gives them) that holds render-origin-relative point
// `p`. A single view holds every point (outside its volume the sampler's address mode answers).
ViewChoice selectView(const std::vector<ShadowView>& lightViews, const glm::dvec3& p);

// The view itself, or nullptr when the light has none.
const ShadowView* viewHolding(const std::vector<ShadowView>& lightViews, const glm::dvec3& p);

}  // namespace shadowlab
