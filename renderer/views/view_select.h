#pragma once
// Which of a light's shadow views holds a world point: the one CPU answer, used by the probe, the true-boundary
// search, the cause classifier, the flicker measure, the tuner and the export. The main pass's selection is its
// mirror: shaders/shadow/view_select.glsl (a point light's face, a cascade and its blend; the hardware's cube lookup
// agrees, tested).
#include "views/shadow_view.h"

#include <glm/ext/vector_double3.hpp>

#include <span>
#include <vector>

namespace shadowlab {

struct ViewChoice {
    int view = -1;        // index into the light's views; -1: no view holds the point (no view at all, or a point
                          // beyond a cascaded light's shadow distance: lit)
    int next = -1;        // a cascade's blend band: the view it fades into (-1: none)
    double weight = 0.0;  // the next view's share (0..1): S = mix(S(view), S(next), weight)
};

// Which cascade holds a point `depth` in front of the camera, given each cascade's far depth and blend start
// (nearest first): the GLSL's selectCascade is the same code.
ViewChoice selectCascade(double depth, std::span<const double> farDepths, std::span<const double> blendStarts);

// The cube face a direction from a point light selects: the axis of largest magnitude (ties: X, then Y, then Z), its
// sign's face (>= 0: positive), in GL order +X,-X,+Y,-Y,+Z,-Z.
int cubeFaceOf(const glm::dvec3& fromLight);

// The view of `lightViews` (one light's views, as buildLightViews gives them) that holds render-origin-relative point
// `p`. A single view holds every point (outside its volume the sampler's address mode answers); a cascaded light's
// cascades by the point's depth in front of the camera they were fitted to.
ViewChoice selectView(const std::vector<ShadowView>& lightViews, const glm::dvec3& p);

// The view itself, or nullptr when the light has none.
const ShadowView* viewHolding(const std::vector<ShadowView>& lightViews, const glm::dvec3& p);

}  // namespace shadowlab
