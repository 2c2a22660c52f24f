#pragma once
// A shadow view: one light space rendered into one map layer. A directional or spot light has one view (Single), a
// point light six (CubeFace, index = GL face order +X,-X,+Y,-Y,+Z,-Z). Every tool that asks "which map, which
// matrix" for a light gets its views from buildLightViews: the one place that knows how many views a light has and
// how each is fitted, so a new kind or fit mode is a new builder here, not a new branch in every caller.
#include "light/light_space.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <glm/ext/vector_double3.hpp>

#include <compare>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

enum class ShadowViewKind { Single, CubeFace };

// Names a view across frames: the map cache and the per-view tools key on it.
struct ShadowViewId {
    std::size_t light = 0;
    ShadowViewKind kind = ShadowViewKind::Single;
    int index = 0;
    auto operator<=>(const ShadowViewId&) const = default;
};

struct ShadowView {
    std::size_t light = 0;  // index into the frame's (effective) lights
    ShadowViewKind kind = ShadowViewKind::Single;
    int index = 0;          // CubeFace: the face (0..5); Single: 0
    LightSpace space;       // render-origin-relative
    int cubeFace() const { return kind == ShadowViewKind::CubeFace ? index : -1; }
    ShadowViewId id() const { return {light, kind, index}; }
};

// "light 2", "light 2 +X": how reports, stats and overlays name a view.
std::string viewName(std::size_t light, ShadowViewKind kind, int index);
inline std::string viewName(const ShadowView& v) { return viewName(v.light, v.kind, v.index); }
// The view's part of a name, as `--view` takes it: "" for a light's only view, "+X" for a cube face.
std::string viewSuffix(ShadowViewKind kind, int index);

// The view of `lightViews` (one light's) that `--view TEXT` names: its suffix ("+X" .. "-Z" for a cube face). nullopt
// with `error` listing the light's views when none matches; a light with one view has nothing to choose.
std::optional<std::size_t> findView(const std::vector<ShadowView>& lightViews, const std::string& text,
                                    std::string& error);

// The render origin every light space and GPU buffer of a scene is relative to: the scene bounds' centre (the origin
// for an empty scene). Large world coordinates then lose no precision in float.
glm::dvec3 renderOriginOf(const Bounds& bounds);

// The views of light `light` (index `lightIndex`) for a scene with these bounds, relative to `origin`: nullopt with
// `error` ("lights.N: ...") when they cannot be finite. Whether the light is enabled or casts is the caller's
// business: the views are those it would have.
std::optional<std::vector<ShadowView>> buildLightViews(const LightSettings& light, std::size_t lightIndex,
                                                       const Bounds& bounds, const glm::dvec3& origin,
                                                       std::string& error);

}  // namespace shadowlab
