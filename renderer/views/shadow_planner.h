#pragma once
// The shadow planner: which views a frame needs and why. Two steps, both pure (no GL), so they are tested alone:
//  1. planShadowViews: (settings, scene bounds, camera, casters) -> every casting light's views, grouped into map arrays
//     with a layer each, and the lights that have no view with the reason;
//  2. decideView: (what a view's map was last rendered from, what it would be rendered from now, whether the camera
//     sees its volume) -> render, clear, keep or skip it, with the reason in the key table's words.
// The Renderer allocates the arrays the plan names and carries out the decisions.
#include "scene/scene.h"
#include "settings/settings.h"
#include "views/map_group.h"
#include "views/shadow_view.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

// A caster's render-origin-relative bounding sphere; `finite` false: its size is unknown (it is always drawn).
struct CasterSphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
    bool finite = false;
};

// Whether a caster can write to a view's map: its sphere meets the view's volume. A directional view keeps casters
// in front of its near plane (depth clamp), so only its sides and far plane cull.
bool casterInVolume(const CasterSphere& caster, const LightSpace& space);

struct PlannedView {
    ShadowView view;
    MapGroup group;
    int layer = 0;             // the view's layer in its group's array (a cube array: 6 per light)
    int castersInVolume = 0;
};

struct LightWithoutView {
    std::size_t light = 0;
    std::string reason;  // "skipped: the light is off (enabled false)"
};

struct ShadowPlan {
    Settings settings;                     // the frame's lights; a refused resolution replaced by the kept map's
    std::vector<PlannedView> views;        // every casting light's views, in light order
    std::vector<LightWithoutView> lightsWithoutViews;
    std::map<MapGroup, int> layers;        // each array's layer count
    std::vector<std::string> warnings;
    std::string error;                     // not empty: no frame (a light's views cannot be built)
    // The views of light `light`, in order (empty when it has none).
    std::vector<ShadowView> lightViews(std::size_t light) const;
};

// The map a light has now, kept when a new resolution is refused.
struct KeptMap {
    int resolution = 0;
    DepthFormat format = DepthFormat::D32F;
};

// `effective`: the frame's lights with useSceneLights resolved. `keptMap(light)`: that light's current map, if any.
// `camera`: the frame's (cascades follow it); nullptr where there is none.
ShadowPlan planShadowViews(const Settings& effective, const Bounds& bounds, const glm::dvec3& origin,
                           const ViewCamera* camera, const std::vector<CasterSphere>& casters, int maxTextureSize,
                           const std::function<std::optional<KeptMap>(std::size_t light)>& keptMap);

// What a view's map was last rendered from; the view runs again only if one of these changed.
struct ViewInputs {
    std::size_t sceneFingerprint = 0;
    glm::dmat4 viewProjection{0.0};
    LightSettings light;               // compared through the key table's shadow-view tags
    std::uint64_t mapGeneration = 0;   // the array was reallocated: its contents are gone
    bool empty = false;                // no caster in its volume: the map is cleared, not drawn
    bool followsCamera = false;        // a cascade: its light space moves with the camera
    std::optional<ViewDepths> depthBounds;  // the depths its cascades span (projection.depthBounds); nullopt: off
    bool operator==(const ViewInputs&) const = default;
};

enum class ViewAction { Render, Clear, Keep, SkipUnseen };

struct ViewDecision {
    ViewAction action = ViewAction::Keep;
    std::string reason;  // "first frame", "shadow.depthBias changed", "skipped: its volume misses the camera's view"
};

// `volumeSeen`: the view's volume meets the camera's (a map no visible pixel reads is rendered once it is seen).
ViewDecision decideView(const std::optional<ViewInputs>& last, const ViewInputs& now, bool volumeSeen);

}  // namespace shadowlab
