#pragma once
// A shadow view: one light space rendered into one map layer. A directional or spot light has one view (Single), a
// point light six (CubeFace, index = GL face order +X,-X,+Y,-Y,+Z,-Z), a directional light with fit = cascades one per
// cascade (Cascade, index 0 = nearest the camera). Every tool that asks "which map, which matrix" for a light gets
// its views from buildLightViews: the one place that knows how many views a light has and how each is fitted. A new
// kind or fit mode is a new builder file (views/*_views.cpp) and a line in its table, not a branch in every caller.
#include "light/light_space.h"
#include "scene/scene.h"
#include "settings/settings.h"
#include "views/view_camera.h"

#include <glm/ext/vector_double3.hpp>

#include <compare>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

enum class ShadowViewKind { Single, CubeFace, Cascade };

// Names a view across frames: the map cache and the per-view tools key on it.
struct ShadowViewId {
    std::size_t light = 0;
    ShadowViewKind kind = ShadowViewKind::Single;
    int index = 0;
    auto operator<=>(const ShadowViewId&) const = default;
};

// A cascade's slice of the camera's frustum: the depths (along the camera's viewing direction, from its eye) it
// answers for. It holds points up to farDepth; from blendStart on it fades into the next cascade.
struct CascadeSlice {
    double nearDepth = 0.0;   // where its own slice begins (the previous cascade's far depth; the camera's near)
    double fitNear = 0.0;     // the nearest depth its volume covers (the previous cascade's blend band starts there)
    double farDepth = 0.0;
    double blendStart = 0.0;  // = farDepth: no band
    ViewCamera camera;        // the camera it was fitted to (its eye and direction measure the depths)
    bool operator==(const CascadeSlice&) const = default;
};

struct ShadowView {
    std::size_t light = 0;  // index into the frame's (effective) lights
    ShadowViewKind kind = ShadowViewKind::Single;
    int index = 0;          // CubeFace: the face (0..5); Cascade: the cascade (0 = nearest); Single: 0
    LightSpace space;       // render-origin-relative
    CascadeSlice slice;     // Cascade only
    int cubeFace() const { return kind == ShadowViewKind::CubeFace ? index : -1; }
    ShadowViewId id() const { return {light, kind, index}; }
};

// "light 2", "light 2 +X": how reports, stats and overlays name a view.
std::string viewName(std::size_t light, ShadowViewKind kind, int index);
inline std::string viewName(const ShadowView& v) { return viewName(v.light, v.kind, v.index); }
// The view's part of a name, as `--view` takes it: "" for a light's only view, "+X" for a cube face, "cascade:1".
std::string viewSuffix(ShadowViewKind kind, int index);

// The view of `lightViews` (one light's) that `--view TEXT` names: its suffix ("+X" .. "-Z" for a cube face). nullopt
// with `error` listing the light's views when none matches; a light with one view has nothing to choose.
std::optional<std::size_t> findView(const std::vector<ShadowView>& lightViews, const std::string& text,
                                    std::string& error);

// The render origin every light space and GPU buffer of a scene is relative to: the scene bounds' centre (the origin
// for an empty scene). Large world coordinates then lose no precision in float.
glm::dvec3 renderOriginOf(const Bounds& bounds);

// What a light's views are built from.
struct ViewBuildInput {
    const LightSettings& light;
    std::size_t lightIndex;
    const Bounds& bounds;
    const glm::dvec3& origin;
    const ViewCamera* camera;  // the frame's camera; nullptr where there is none (fits that follow it then fail)
};

// The views of light `light` (index `lightIndex`) for a scene with these bounds, relative to `origin`, seen by
// `camera` (cascades follow it; nullptr: no camera, and a cascaded light's views cannot be built): nullopt with
// `error` ("lights.N: ...") when they cannot be finite. Whether the light is enabled or casts is the caller's
// business: the views are those it would have.
std::optional<std::vector<ShadowView>> buildLightViews(const LightSettings& light, std::size_t lightIndex,
                                                       const Bounds& bounds, const glm::dvec3& origin,
                                                       const ViewCamera* camera, std::string& error);

}  // namespace shadowlab
