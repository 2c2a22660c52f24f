#include "views/shadow_view.h"

#include "views/view_builders.h"

namespace shadowlab {

std::string viewSuffix(ShadowViewKind kind, int index) {
    switch (kind) {
    case ShadowViewKind::Single: return "";
    case ShadowViewKind::CubeFace: return index >= 0 && index < 6 ? cubeFaces()[std::size_t(index)].name : "?";
    case ShadowViewKind::Cascade: return "cascade:" + std::to_string(index);
    }
    return "";
}

std::string viewName(std::size_t light, ShadowViewKind kind, int index) {
    const std::string suffix = viewSuffix(kind, index);
    return "light " + std::to_string(light) + (suffix.empty() ? "" : " " + suffix);
}

std::optional<std::size_t> findView(const std::vector<ShadowView>& lightViews, const std::string& text,
                                    std::string& error) {
    std::string choices;
    for (std::size_t v = 0; v < lightViews.size(); ++v) {
        const std::string suffix = viewSuffix(lightViews[v].kind, lightViews[v].index);
        if (!suffix.empty() && suffix == text) return v;
        choices += (choices.empty() ? "" : ", ") + suffix;
    }
    const std::string light = lightViews.empty() ? "the light" : "light " + std::to_string(lightViews.front().light);
    error = choices.empty() || lightViews.size() < 2
                ? "--view " + text + ": " + light + " has one view (--view chooses among a point light's cube faces or a " +
                      "cascaded light's cascades)"
                : "--view " + text + ": " + light + " has no such view: it has " + std::to_string(lightViews.size()) +
                      " views (allowed: " + choices + ")";
    return std::nullopt;
}

glm::dvec3 renderOriginOf(const Bounds& bounds) {
    return bounds.centreOrOrigin();
}

std::optional<std::vector<ShadowView>> buildLightViews(const LightSettings& light, std::size_t lightIndex,
                                                       const Bounds& bounds, const glm::dvec3& origin,
                                                       const ViewCamera* camera, std::string& error) {
    const ViewBuildInput in{light, lightIndex, bounds, origin, camera};
    std::string why;
    for (const ViewBuilder& builder : viewBuilders()) {
        if (!builder.applies(light)) continue;
        std::vector<ShadowView> views = builder.build(in, why);
        if (views.empty()) break;
        for (ShadowView& v : views) v.light = lightIndex;
        return views;
    }
    error = "lights." + std::to_string(lightIndex) + ": " + why;
    return std::nullopt;
}

}  // namespace shadowlab
