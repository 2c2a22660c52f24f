#include "views/shadow_planner.h"

#include "light/scene_lights.h"
#include "light/volume_overlap.h"
#include "settings/settings_fields.h"
#include "views/depth_bounds.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

std::string joinReasons(const std::vector<std::string>& parts) {
    std::string out;
    for (const std::string& part : parts) out += (out.empty() ? "" : "; ") + part;
    return out;
}

std::string joinKeys(const std::vector<std::string>& keys) {
    std::string out;
    for (const std::string& key : keys) out += (out.empty() ? "" : ", ") + key;
    return out;
}

// The global keys tagged as changing shadow views (casters.excluded, useSceneLights) that differ between the settings
// a map was rendered with and the frame's; each held settings object is compared once per frame (views share them).
class GlobalKeyChanges {
public:
    explicit GlobalKeyChanges(const Settings& now) : now_(now) {}
    const std::vector<std::string>& since(const std::shared_ptr<const Settings>& held) {
        for (const auto& [settings, keys] : seen_)
            if (settings == held.get()) return keys;
        std::vector<std::string> keys;
        if (!(*held == now_)) keys = diffGlobals(*held, now_, kInvalidatesShadowView).keys;
        seen_.emplace_back(held.get(), std::move(keys));
        return seen_.back().second;
    }

private:
    const Settings& now_;
    std::vector<std::pair<const Settings*, std::vector<std::string>>> seen_;
};

// The keys that change a light's views (the key table's shadow-view tags) whose values differ between what a map
// holds and now, by name: the light's own ("shadow.depthBias"), then global ones ("casters.excluded").
std::vector<std::string> changedKeys(const MapContents& held, const MapContents& now, GlobalKeyChanges& globals) {
    std::vector<std::string> keys = diffLight(held.light, now.light, kInvalidatesShadowView).keys;
    for (const std::string& key : globals.since(held.settings)) keys.push_back(key);
    return keys;
}

// Why a view whose map holds `held` must render again to hold `now`, in the key table's words; "" when nothing that
// changes its map did. `kept`: its map's layer survived (same array, same layer, not reallocated).
std::string changeReason(const MapContents& held, const MapContents& now, ShadowViewKind kind, bool kept,
                         GlobalKeyChanges& globals) {
    std::vector<std::string> reasons;
    const std::vector<std::string> keys = changedKeys(held, now, globals);
    if (!keys.empty()) reasons.push_back(joinKeys(keys) + " changed");
    if (now.sceneFingerprint != held.sceneFingerprint) reasons.push_back("scene changed");
    if (keys.empty() && now.viewProjection != held.viewProjection)
        reasons.push_back(now.depthBounds != held.depthBounds      ? "the depth bounds moved"
                          : kind == ShadowViewKind::Cascade ? "the camera moved (the cascade follows it)"
                                                            : "light space changed");
    if (reasons.empty() && !kept) reasons.push_back("shadow map reallocated");
    return joinReasons(reasons);
}

// The map the previous plan gave light `light` (its views share one size and format).
std::optional<MapGroup> previousMap(const ShadowPlan* previous, std::size_t light) {
    if (!previous) return std::nullopt;
    for (const PlannedView& p : previous->views)
        if (p.view.light == light) return p.group;
    return std::nullopt;
}

// Why a view the previous plan lacks renders: the keys that gave its light other views ("type changed",
// "projection.cascadeCount changed"), else "new view".
std::string newViewReason(const ShadowPlan& previous, std::size_t light, const MapContents& now,
                          GlobalKeyChanges& globals) {
    for (const PlannedView& p : previous.views) {
        if (p.view.light != light || !p.holds) continue;
        const std::vector<std::string> keys = changedKeys(*p.holds, now, globals);
        if (!keys.empty()) return joinKeys(keys) + " changed";
    }
    return "new view";
}

// Whether a caster can write to the view's map. Asked only of a view that must render: a still frame tests no
// caster, and the first caster found ends the search.
bool anyCasterIn(const std::vector<CasterSphere>& casters, const LightSpace& space) {
    return std::any_of(casters.begin(), casters.end(), [&](const CasterSphere& c) { return casterInVolume(c, space); });
}

bool isStatic(const PlanInputs& in, std::size_t caster) {
    return in.staticCasters && caster < in.staticCasters->size() && (*in.staticCasters)[caster];
}

// "Spinner moved", "car 1, car 2 moved", "car 1, car 2, car 3 and 4 more moved".
std::string movedReason(const std::vector<const MovedCaster*>& moved) {
    std::string names;
    const std::size_t shown = std::min<std::size_t>(moved.size(), 3);
    for (std::size_t i = 0; i < shown; ++i) names += (i ? ", " : "") + moved[i]->name;
    if (moved.size() > shown) names += " and " + std::to_string(moved.size() - shown) + " more";
    return names + " moved";
}

// How the casters' motion since the map was drawn touches a view whose keys, light space and geometry are unchanged.
struct ViewMotion {
    bool stale = false;                       // the map misses a pose: it must be drawn again
    bool consecutive = false;                 // drawn at the previous frame's pose: `touching` is all that changed
    std::vector<const MovedCaster*> touching; // moved casters it held before or holds now
    std::string reason;
};

ViewMotion motionOf(const PlanInputs& in, const MapContents& held, const LightSpace& space) {
    ViewMotion m;
    const std::uint64_t pose = in.motion ? in.motion->pose : 0;
    if (held.pose == pose) return m;
    // `moved` is this frame's motion (pose - 1 to pose); a map drawn at an older pose, or at pose - 1 on a frame where
    // nothing moves (it waited: everyNthFrame), missed a motion nobody lists any more.
    if (!in.motion || held.pose + 1 != pose || in.motion->moved.empty()) {
        m.stale = true;
        m.reason = "casters moved while it was not drawn";
        return m;
    }
    m.consecutive = true;
    for (const MovedCaster& c : in.motion->moved)
        if (casterInVolume(c.before, space) || casterInVolume(c.after, space)) m.touching.push_back(&c);
    m.stale = !m.touching.empty();
    if (m.stale) m.reason = movedReason(m.touching);
    return m;
}

// A cachedStatic view where only casters moved since the previous frame: the rectangle the dynamic movers cover
// (before and after), redrawn from the cached depth with the dynamic casters that can write in it, when that pays.
// Static movers stay where the cache holds them (the cache error casters.static asks for), with a warning.
void planStaticPlusDynamic(PlannedView& p, const PlanInputs& in, const ViewMotion& motion, ShadowPlan& plan) {
    const LightSpace& space = p.view.space;
    std::vector<const MovedCaster*> dynamicMovers;
    for (const MovedCaster* c : motion.touching) {
        if (!isStatic(in, c->caster)) {
            dynamicMovers.push_back(c);
            continue;
        }
        const std::string warning = "casters.static: " + c->name + " moved but is a static caster: light " +
                                    std::to_string(p.view.light) +
                                    "'s cached depth keeps it where it was (a cache error; list it in casters.dynamic)";
        if (std::find(plan.warnings.begin(), plan.warnings.end(), warning) == plan.warnings.end())
            plan.warnings.push_back(warning);
    }
    if (dynamicMovers.empty()) {
        p.action = ViewAction::Keep;
        p.cache = CacheState::Reused;
        p.reason = "only static casters moved (" + movedReason(motion.touching) + "; its cached depth keeps them)";
        return;
    }
    TexelRect rect;
    for (const MovedCaster* c : dynamicMovers) {
        rect.extend(casterTexels(c->before, space));
        rect.extend(casterTexels(c->after, space));
    }
    std::vector<std::size_t> draw;
    std::size_t staticInVolume = 0;
    for (std::size_t i = 0; i < in.casters.size(); ++i) {
        if (!casterInVolume(in.casters[i], space)) continue;
        if (isStatic(in, i)) ++staticInVolume;
        else if (casterTexels(in.casters[i], space).overlaps(rect)) draw.push_back(i);
    }
    p.action = ViewAction::Render;
    p.reason = movedReason(dynamicMovers);
    if (!staticPlusDynamicPays(staticInVolume)) {
        p.cache = CacheState::Full;
        p.reason += " (no static caster in its volume: its cached depth is empty)";
        return;
    }
    p.cache = CacheState::StaticPlusDynamic;
    p.rect = rect;
    p.dynamicCasters = std::move(draw);
}

// Decides one view: its action, its reason and what its map holds once the frame has carried them out.
// `layersNow`: its array's layer count this frame.
void decide(PlannedView& p, const PlanInputs& in, MapContents now, int layersNow,
            const std::shared_ptr<const Settings>& requested, GlobalKeyChanges& globals, ShadowPlan& plan) {
    const PlannedView* before = in.previous ? in.previous->find(p.view.id()) : nullptr;
    // Its map still holds what it held: the same layer of an array that was not reallocated (the Renderer
    // reallocates an array when its layer count changes).
    const bool kept = before && before->holds && before->group == p.group && before->layer == p.layer &&
                      in.previous->layers.at(before->group) == layersNow;
    const ShadowMapSettings& shadow = now.light.shadow;
    const bool cachedStatic = shadow.update == ShadowUpdate::CachedStatic;
    now.pose = in.motion ? in.motion->pose : 0;
    std::string reason;
    if (!in.forceReason.empty()) reason = in.forceReason;
    else if (!in.previous) reason = "first frame";
    else if (!before) reason = newViewReason(*in.previous, p.view.light, now, globals);
    else if (!before->holds) reason = "its map holds nothing yet (new or reallocated while unseen)";
    else reason = changeReason(*before->holds, now, p.view.kind, kept, globals);

    // A stable cascade of a cachedStatic light that only followed the camera: its cached static depth scrolls when
    // the move is whole texels of the light's grid; otherwise the reason says why it is drawn whole.
    CascadeScroll scroll;
    if (!reason.empty() && in.forceReason.empty() && cachedStatic && kept && before->holds->staticCache &&
        p.view.kind == ShadowViewKind::Cascade && now.light.projection.cascadeFit == CascadeFit::Stable &&
        changedKeys(*before->holds, now, globals).empty() && now.sceneFingerprint == before->holds->sceneFingerprint) {
        scroll = cascadeScroll(before->holds->viewProjection, now.viewProjection, p.view.space.resolution);
        if (scroll.shift && cascadePages(p.view.space, {0, 0, 1, 1}).empty())
            scroll = {std::nullopt, "its centre is off its texel grid or its resolution is odd"};
        if (!scroll.shift) reason += " (not scrolled: " + scroll.why + ")";
    }

    // Only casters moved: the views they touch (before or now) draw again, by the light's policy.
    ViewMotion motion;
    if (reason.empty()) {
        motion = motionOf(in, *before->holds, p.view.space);
        if (motion.stale) reason = motion.reason;
        else if (shadow.update == ShadowUpdate::EveryFrame) reason = "shadow.update everyFrame";
    }
    const bool onlyMotion = motion.stale;
    const auto reuse = [&](std::string why, bool posedNow) {
        p.action = ViewAction::Keep;
        p.cache = CacheState::Reused;
        p.reason = std::move(why);
        p.holds = before->holds;
        if (posedNow) p.holds->pose = now.pose;
    };
    if (reason.empty()) {
        reuse(motion.consecutive ? "unchanged: nothing that moved is in its volume"
                                 : "unchanged: light, casters and shadow settings are the same",
              true);
        return;
    }
    if (onlyMotion && shadow.update == ShadowUpdate::EveryNthFrame &&
        in.frame % std::uint64_t(std::max(shadow.updateInterval, 1)) != 0) {
        const std::uint64_t n = std::uint64_t(std::max(shadow.updateInterval, 1));
        reuse("waits " + std::to_string(n - in.frame % n) + " frame(s) for its update (shadow.update everyNthFrame, " +
                  "every " + std::to_string(n) + "): " + reason,
              false);
        return;
    }
    if (in.cameraViewProjection && !volumesOverlap(p.view.space.volumeViewProjection(), *in.cameraViewProjection)) {
        // A map no visible pixel reads is rendered once the camera sees its volume.
        p.action = ViewAction::SkipUnseen;
        p.cache = CacheState::Reused;
        p.reason = "skipped: its volume misses the camera's view";
        if (kept) p.holds = before->holds;
        return;
    }
    if (scroll.shift) {
        // Every dynamic caster is drawn over the scrolled static depth: the motion since its last draw is covered.
        p.action = ViewAction::Render;
        p.cache = CacheState::Scrolled;
        p.fromStaticCache = true;
        p.scroll = *scroll.shift;
        p.reason = describeScroll(p.scroll, p.view.space.resolution);
        p.holds = std::move(now);
        p.holds->settings = requested;
        p.holds->staticCache = true;
        return;
    }
    if (onlyMotion && cachedStatic && motion.consecutive && before->holds->staticCache) {
        planStaticPlusDynamic(p, in, motion, plan);
        if (p.action == ViewAction::Keep) {
            p.holds = before->holds;
            p.holds->pose = now.pose;
            return;
        }
        p.fromStaticCache = true;
        p.holds = std::move(now);
        p.holds->settings = requested;
        p.holds->staticCache = true;
        return;
    }
    if (!anyCasterIn(in.casters, p.view.space)) {
        p.action = ViewAction::Clear;
        p.cache = CacheState::Full;
        p.reason = "skipped: no caster in its volume (map cleared)";
        p.holds = std::move(now);
        p.holds->settings = requested;
        return;
    }
    p.action = ViewAction::Render;
    p.cache = CacheState::Full;
    p.fromStaticCache = cachedStatic;
    p.reason = std::move(reason);
    p.holds = std::move(now);
    p.holds->settings = requested;
    p.holds->staticCache = cachedStatic;
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

const PlannedView* ShadowPlan::find(const ShadowViewId& id) const {
    for (const PlannedView& p : views)
        if (p.view.id() == id) return &p;
    return nullptr;
}

ShadowPlan planShadowViews(const PlanInputs& in) {
    ShadowPlan plan;
    plan.settings = withEffectiveLights(in.settings, in.scene);
    for (std::size_t i = 0; i < plan.settings.lights.size(); ++i) {
        LightSettings& light = plan.settings.lights[i];
        if (!light.enabled || !light.castsShadows) {
            plan.lightsWithoutViews.push_back(
                {i, !light.enabled ? "skipped: the light is off (enabled false)"
                                   : "skipped: castsShadows is off (lit everywhere it reaches)"});
            continue;
        }
        // A size the GPU refuses keeps the light's previous map (and says so); with no map at all there is no frame.
        if (!shadowResolutionRefusal(light.shadow.resolution, in.maxTextureSize, "").empty()) {
            const std::optional<MapGroup> kept = previousMap(in.previous, i);
            const std::string refusal = shadowResolutionRefusal(
                light.shadow.resolution, in.maxTextureSize,
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
        const auto views = buildLightViews(light, i, in.scene.bounds, in.origin, in.camera, error);
        if (!views) {
            plan.error = error;
            return plan;
        }
        const MapGroup group = mapGroupOf(light);
        for (const ShadowView& view : *views) {
            PlannedView p;
            p.view = view;
            p.group = group;
            p.layer = plan.layers[group]++;
            plan.views.push_back(std::move(p));
        }
    }

    // Each view against what its map holds. The frame's settings are copied once, shared by the maps it renders,
    // and only when one renders (a still frame copies nothing).
    std::shared_ptr<const Settings> requested;
    GlobalKeyChanges globals(in.settings);
    for (PlannedView& p : plan.views) {
        const LightSettings& light = plan.settings.lights[p.view.light];
        MapContents now{nullptr, light, in.sceneFingerprint, p.view.space.viewProjection(),
                        p.view.kind == ShadowViewKind::Cascade && in.camera ? cascadeDepthBounds(light, *in.camera)
                                                                            : std::nullopt};
        decide(p, in, std::move(now), plan.layers.at(p.group), requested, globals, plan);
        if (p.holds && !p.holds->settings) p.holds->settings = requested = std::make_shared<const Settings>(in.settings);
    }
    return plan;
}

const char* cacheStateName(CacheState state) {
    switch (state) {
    case CacheState::Reused: return "reused";
    case CacheState::StaticPlusDynamic: return "static + dynamic";
    case CacheState::Scrolled: return "scrolled";
    case CacheState::Full: return "full";
    }
    return "?";
}

std::string describeUpdate(const PlannedView& view) { return std::string(cacheStateName(view.cache)) + ": " + view.reason; }

bool staticPlusDynamicPays(std::size_t staticInVolume) { return staticInVolume > 0; }

int viewsToRender(const ShadowPlan& plan) {
    return int(std::count_if(plan.views.begin(), plan.views.end(),
                             [](const PlannedView& p) { return p.action == ViewAction::Render; }));
}

}  // namespace shadowlab
