// A point light's six cube faces: 90-degree perspective views in GL's face order.
#include "views/view_builders.h"

namespace shadowlab {

bool cubeFacesApply(const LightSettings& light) { return light.type == LightType::Point; }

std::vector<ShadowView> buildCubeFaceViews(const ViewBuildInput& in, std::string& why) {
    const auto faces = buildCubeFaceSpaces(in.light, in.bounds, in.origin, why);
    if (!faces) return {};
    std::vector<ShadowView> views;
    for (int f = 0; f < 6; ++f) views.push_back({in.lightIndex, ShadowViewKind::CubeFace, f, (*faces)[std::size_t(f)], {}});
    return views;
}

}  // namespace shadowlab
