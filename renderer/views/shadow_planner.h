#pragma once
// The shadow planner: (scene, settings, camera, the previous frame's plan) -> the views this frame needs, each with
// its action and reason. Pure (no GL), so it is tested alone: it builds every casting light's views, groups them into
// map arrays with a layer each, and compares each view with what its map holds (the previous plan's record of it):
// a view renders again only when a key the key table tags as changing shadow views changed (named in the reason),
// its light space moved, a caster moved in or out of its volume (CasterMotion: only the views a motion touches) or its
// map was reallocated. Each light's update policy (shadow.update) decides how: every frame, on change, every Nth
// frame, or from a cached depth of its static casters with only the moving ones drawn over it (static + dynamic). The Renderer allocates the arrays the plan
// names and carries out each view's action; the plan it carried out is the next frame's `previous`.
#include "scene/scene.h"
#include "settings/settings.h"
#include "views/cascade_scroll.h"
#include "views/caster_motion.h"
#include "views/map_group.h"
#include "views/shadow_view.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

// Whether a caster can write to a view's map: its sphere meets the view's volume. A directional view keeps casters
// in front of its near plane (depth clamp), so only its sides and far plane cull.
bool casterInVolume(const CasterSphere& caster, const LightSpace& space);

// What a view's map holds: the inputs it was last rendered (or cleared) from.
struct MapContents {
    std::shared_ptr<const Settings> settings;  // the frame's settings as requested (useSceneLights, casters.excluded)
    LightSettings light;                       // its light as the frame used it (a scene light with its settings)
    std::size_t sceneFingerprint = 0;
    glm::dmat4 viewProjection{0.0};
    std::optional<ViewDepths> depthBounds;  // a cascade's seen depths (projection.depthBounds); nullopt: off
    std::uint64_t pose = 0;                 // the casters' poses it was drawn at (CasterMotion::pose)
    bool staticCache = false;               // the view's cached static depth was drawn with it (shadow.update cachedStatic)
};

enum class ViewAction { Render, Clear, Keep, SkipUnseen };

// What a view's map got this frame, as the views table says it: reused (kept or skipped), static + dynamic (its
// cached static depth copied within a rectangle and the moving casters drawn over it), scrolled (a stable cascade's
// cached static depth moved by whole texels, only the strips that came into view drawn) or full (every caster drawn).
enum class CacheState { Reused, StaticPlusDynamic, Scrolled, Full };
const char* cacheStateName(CacheState state);  // "reused", "static + dynamic", "scrolled", "full"

struct PlannedView {
    ShadowView view;
    MapGroup group;
    int layer = 0;             // the view's layer in its group's array (a cube array: 6 per light)
    ViewAction action = ViewAction::Keep;  // Clear: no caster in its volume (tested only for a view that must run)
    std::string reason;        // "first frame", "shadow.depthBias changed", "skipped: its volume misses the camera's view"
    // What its map holds once the frame has carried out the plan; nullopt: nothing usable (never rendered, or its
    // array was reallocated while it was skipped).
    std::optional<MapContents> holds;
    CacheState cache = CacheState::Reused;
    // A Render of a cachedStatic light's view: Full draws its static casters into its cached depth first, copies it
    // whole and draws its dynamic casters over it; StaticPlusDynamic copies the cached depth within `rect` only and
    // draws `dynamicCasters` (the dynamic casters that can write inside it) scissored to it.
    bool fromStaticCache = false;
    TexelRect rect;
    std::vector<std::size_t> dynamicCasters;  // indices into PlanInputs::casters
    // Scrolled: how far its cached static depth moves (views/cascade_scroll.h); the exposed strips get the static
    // casters, then every dynamic caster is drawn over the whole map.
    TexelShift scroll;
};

// "static + dynamic: car 3 moved", "full: shadow.depthBias changed", "reused: unchanged: ...": the views table's line.
std::string describeUpdate(const PlannedView& view);

struct LightWithoutView {
    std::size_t light = 0;
    std::string reason;  // "skipped: the light is off (enabled false)"
};

struct ShadowPlan {
    Settings settings;                     // the frame's effective lights; a refused resolution replaced by the kept map's
    std::vector<PlannedView> views;        // every casting light's views, in light order
    std::vector<LightWithoutView> lightsWithoutViews;
    std::map<MapGroup, int> layers;        // each array's layer count
    std::vector<std::string> warnings;
    std::string error;                     // not empty: no frame (a light's views cannot be built)
    // The views of light `light`, in order (empty when it has none).
    std::vector<ShadowView> lightViews(std::size_t light) const;
    // The view with this id, nullptr when the plan has none.
    const PlannedView* find(const ShadowViewId& id) const;
};

struct PlanInputs {
    const Scene& scene;                  // its bounds; its lights with useSceneLights
    const Settings& settings;            // as requested (validated)
    glm::dvec3 origin{0.0};              // the render origin every light space is relative to
    const ViewCamera* camera = nullptr;  // the frame's (cascades follow it); nullptr where there is none
    // The camera's clip-from-world (render-origin-relative): a view whose volume it misses is not rendered (its map
    // is read by no visible pixel). nullopt: every volume counts as seen.
    std::optional<glm::dmat4> cameraViewProjection;
    const std::vector<CasterSphere>& casters;
    std::size_t sceneFingerprint = 0;    // the scene's geometry (renderer.h: sceneFingerprint)
    int maxTextureSize = 16384;
    const ShadowPlan* previous = nullptr;  // the plan the previous frame carried out; nullptr: the first frame
    std::string forceReason;               // not empty: every view renders, for this reason (benchmarks)
    const CasterMotion* motion = nullptr;  // what moved since the previous frame; nullptr: nothing (pose 0)
    // Per caster: 1 static (a cachedStatic light keeps it in its cached depth), 0 dynamic; nullptr: all dynamic.
    const std::vector<char>* staticCasters = nullptr;
    std::uint64_t frame = 0;               // frames rendered before this one (everyNthFrame renders when N divides it)
};

// Whether a cachedStatic view whose dynamic casters moved is redrawn from its cached depth (static + dynamic) rather
// than in full: when its volume holds a static caster. Static + dynamic then draws a subset of a full redraw's
// casters (the dynamic ones meeting the rectangle, never a static one) for one copy of the rectangle; with no static
// caster in the volume the cached depth is empty and the copy buys nothing.
bool staticPlusDynamicPays(std::size_t staticInVolume);

// The frame's plan. A resolution the GPU refuses keeps the light's map of the previous plan (a warning); with no
// previous map there is no frame (ShadowPlan::error).
ShadowPlan planShadowViews(const PlanInputs& in);

// The views the plan renders (ViewAction::Render).
int viewsToRender(const ShadowPlan& plan);

}  // namespace shadowlab
