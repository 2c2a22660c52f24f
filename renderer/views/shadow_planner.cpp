#include "views/shadow_planner.h"

#include "settings/settings_fields.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

std::string joinReasons(const std::vector<std::string>& parts) {
    std::string out;
    for (const std::string& part : parts) out += (out.empty() ? "" : "; ") + part;
    return out;
}

// Why a view's inputs changed since its map was rendered, in the key table's words; "" when nothing that changes
// the map did.
std::string changeReason(const std::optional<ViewInputs>& last, const ViewInputs& now) {
    if (!last) return "first frame";
    if (now.mapGeneration != last->mapGeneration) return "shadow map reallocated";
    std::vector<std::string> reasons;
    if (now.sceneFingerprint != last->sceneFingerprint) reasons.push_back("scene changed");
    // The light's keys that change its views (the key table's shadow-view tags), by name.
    std::string keys;
    for (const std::string& key : diffLight(last->light, now.light).keys) {
        const SettingsField* field = findSettingsField("lights.0." + key);
        if (field && (field->invalidates & kInvalidatesShadowView)) keys += (keys.empty() ? "" : ", ") + key;
    }
    if (!keys.empty()) reasons.push_back(keys + " changed");
    if (keys.empty() && now.viewProjection != last->viewProjection)
        reasons.push_back(now.depthBounds != last->depthBounds ? "the depth bounds moved"
                          : now.followsCamera                  ? "the camera moved (the cascade follows it)"
                                                               : "light space changed");
    if (now.empty != last->empty)
        reasons.push_back(now.empty ? "no caster in its volume any more" : "casters entered its volume");
    return joinReasons(reasons);
}

}  // namespace

bool casterInVolume(const CasterSphere& caster, const LightSpace& light) {
    if (!caster.finite) return true;  // cannot tell: draw it (non-finite vertices are dropped at load)
    const glm::dvec3 c = glm::dvec3(light.view * glm::dvec4(caster.center, 1.0));
    const double r = caster.radius;
    const double depth = -c.z;  // distance along the light
    if (depth - r > light.farPlane) return false;
    if (!light.perspective) {
        // Casters in front of the near plane still cast (depth clamp), so only the sides and far plane cull.
        const double half = 0.5 * light.orthoSize;
        return std::abs(c.x) - r <= half && std::abs(c.y) - r <= half;
    }
    if (depth + r < 0.0) return false;  // entirely behind the light
    // Sphere against the four side planes of the square frustum (normals pointing inward).
    const double t = light.tanHalfFov;
    const double norm = std::sqrt(1.0 + t * t);
    for (int axis = 0; axis < 2; ++axis) {
        const double lateral = axis == 0 ? c.x : c.y;
        if ((depth * t - lateral) / norm < -r) return false;
        if ((depth * t + lateral) / norm < -r) return false;
    }
    return true;
}

std::vector<ShadowView> ShadowPlan::lightViews(std::size_t light) const {
    std::vector<ShadowView> out;
    for (const PlannedView& p : views)
        if (p.view.light == light) out.push_back(p.view);
    return out;
}

ShadowPlan planShadowViews(const Settings& effective, const Bounds& bounds, const glm::dvec3& origin,
                           const ViewCamera* camera, const std::vector<CasterSphere>& casters, int maxTextureSize,
                           const std::function<std::optional<KeptMap>(std::size_t light)>& keptMap) {
    ShadowPlan plan;
    plan.settings = effective;
    for (std::size_t i = 0; i < plan.settings.lights.size(); ++i) {
        LightSettings& light = plan.settings.lights[i];
        if (!light.enabled || !light.castsShadows) {
            plan.lightsWithoutViews.push_back(
                {i, !light.enabled ? "skipped: the light is off (enabled false)"
                                   : "skipped: castsShadows is off (lit everywhere it reaches)"});
            continue;
        }
        // A size the GPU refuses keeps the light's previous map (and says so); with no map at all there is no frame.
        // The kept map is looked up only then: an allowed size costs no search.
        if (!shadowResolutionRefusal(light.shadow.resolution, maxTextureSize, "").empty()) {
            const std::optional<KeptMap> kept = keptMap ? keptMap(i) : std::nullopt;
            const std::string refusal = shadowResolutionRefusal(
                light.shadow.resolution, maxTextureSize,
                kept ? "keeping the " + std::to_string(kept->resolution) + "² map" : "no shadow map yet");
            if (!kept) {
                plan.error = refusal;
                return plan;
            }
            plan.warnings.push_back(refusal);
            light.shadow.resolution = kept->resolution;
            light.shadow.format = kept->format;
        }
        std::string error;
        const auto views = buildLightViews(light, i, bounds, origin, camera, error);
        if (!views) {
            plan.error = error;
            return plan;
        }
        const bool cube = views->front().kind == ShadowViewKind::CubeFace;
        const MapGroup group{cube, light.shadow.resolution, light.shadow.format, light.shadow.reversedZ};
        for (const ShadowView& view : *views) {
            PlannedView p{view, group, plan.layers[group]++, 0};
            for (const CasterSphere& caster : casters) p.castersInVolume += casterInVolume(caster, view.space);
            plan.views.push_back(std::move(p));
        }
    }
    return plan;
}

ViewDecision decideView(const std::optional<ViewInputs>& last, const ViewInputs& now, bool volumeSeen) {
    const std::string reason = changeReason(last, now);
    if (reason.empty()) return {ViewAction::Keep, "unchanged: light, casters and shadow settings are the same"};
    // A map no visible pixel reads is rendered once the camera sees its volume.
    if (!volumeSeen) return {ViewAction::SkipUnseen, "skipped: its volume misses the camera's view"};
    if (now.empty) return {ViewAction::Clear, "skipped: no caster in its volume (map cleared)"};
    return {ViewAction::Render, reason};
}

}  // namespace shadowlab
