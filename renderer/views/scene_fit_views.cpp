// The scene fit: one view around the whole scene (directional: its bounding sphere; spot: the cone, near and far
// around the scene), or the user's manual size and planes.
#include "views/view_builders.h"

namespace shadowlab {

bool sceneFitApplies(const LightSettings& light) { return light.type != LightType::Point; }

std::vector<ShadowView> buildSceneFitView(const ViewBuildInput& in, std::string& why) {
    const auto space = buildLightSpace(in.light, in.bounds, in.origin, why);
    if (!space) return {};
    return {{in.lightIndex, ShadowViewKind::Single, 0, *space, {}}};
}

}  // namespace shadowlab
