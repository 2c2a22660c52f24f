#pragma once
// The light's view and projection: built in double precision, relative to a render origin (large world
// coordinates lose no precision), with a view basis that stays finite and continuous for a light pointing straight
// down (the textbook's fixed up=(0,1,0) gives NaN there).
#include "scene/scene.h"
#include "settings/settings.h"

#include <glm/mat4x4.hpp>
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>

#include <algorithm>
#include <array>
#include <optional>
#include <string>

namespace shadowlab {

struct LightSpace {
    glm::dmat4 view{1.0};        // render-origin-relative world -> light view
    glm::dmat4 projection{1.0};  // light view -> clip
    glm::dmat4 viewProjection() const { return projection * view; }
    bool perspective = false;
    int cubeFace = -1;                     // a point light's face (GL order +X,-X,+Y,-Y,+Z,-Z); -1 otherwise
    glm::dvec3 direction{0.0, -1.0, 0.0};  // unit, the direction light travels (spot: the cone axis)
    glm::dvec3 position{0.0};              // spot: world position; directional: the eye of the ortho volume
    double nearPlane = 0.0;
    double farPlane = 1.0;
    double orthoSize = 0.0;        // directional: full width of the volume
    double tanHalfFov = 0.0;       // spot
    double texelWorldSize = 0.0;   // directional: constant; spot: at the scene centre's distance
    int resolution = 1;
    // The map's depth convention. Normal: GL clip depth [-1, 1] (no glClipControl), window depth = 0.5 ndc + 0.5,
    // near 0, far 1, compared GL_LEQUAL. Reversed-Z: the projection maps near to 1 and far to 0 under
    // glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) (window depth = ndc), compared GL_GEQUAL.
    bool reversedZ = false;
    // The world size of one shadow-map texel at distance `viewDepth` from the light (spot) or anywhere (directional).
    double texelSizeAt(double viewDepth) const;
    // The stored (window) depth of a clip-space point, in this view's convention: the one CPU copy of the shader's
    // toLightTexture depth (shaders/shadow/light_data.glsl).
    double windowDepth(const glm::dvec4& clip) const;
    // Texture coordinates (x, y in [0, 1] inside the map) and window depth of a clip-space point.
    glm::dvec3 textureOf(const glm::dvec4& clip) const;
    // viewProjection() in GL's [-1, 1] clip convention whatever the depth convention: the same volume, for volume
    // tests and drawings that take the clip cube's corners.
    glm::dmat4 volumeViewProjection() const;
    // The depth of the far plane / of "nothing drawn" (what the map is cleared to): 1, or 0 reversed.
    double farDepth() const { return reversedZ ? 0.0 : 1.0; }
    // A stored depth as the normal convention would store it (0 at near, 1 at far): 1 - d reversed. In double, exact
    // for every stored float; for distances and orderings, never for the format's step r (that follows the stored
    // value).
    double normalDepth(double stored) const { return reversedZ ? 1.0 - stored : stored; }
    // What the comparison says: a receiver at depth `receiver` is lit by a stored depth (LEQUAL, or GEQUAL).
    bool litBy(double receiver, double stored) const { return reversedZ ? receiver >= stored : receiver <= stored; }
    // The receiver depth the shader compares: beyond the far plane it compares as if on it.
    double clampToFar(double depth) const { return reversedZ ? std::max(depth, 0.0) : std::min(depth, 1.0); }
};

// The border depth a sampler of this convention returns for the user's sampler.borderDepth (whose meaning, 1 = lit
// outside, is the normal convention's): 1 - borderDepth reversed.
float conventionBorderDepth(float borderDepth, bool reversedZ);

// A rotation-minimal basis around `direction`: the frame that takes straight-down (0,-1,0) to `direction` with
// the smallest rotation. Continuous everywhere except a tiny cap around straight up, where a fixed frame is used.
// Columns: right, up, back (= -direction). `direction` must be finite and non-zero.
glm::dmat3 lightBasis(const glm::dvec3& direction);

// Builds the light space of a directional or spot light for the scene bounds; nullopt with `error` set if it
// cannot be finite (or the light is a point light: see buildCubeFaceSpaces). `origin` is subtracted from every world
// position before the matrices apply (camera-relative rendering).
std::optional<LightSpace> buildLightSpace(const LightSettings& light, const Bounds& bounds, const glm::dvec3& origin,
                                          std::string& error);
// The same for the settings' first light.
std::optional<LightSpace> buildLightSpace(const Settings& settings, const Bounds& bounds, const glm::dvec3& origin,
                                          std::string& error);

// A directional light's orthographic view: a square volume of half-width `halfSize` around the eye's axis, depths
// [nearPlane, farPlane] from `eye` along the light (render-origin-relative), in the light's depth convention and at its
// resolution. `direction` is unit. What the scene fit and each cascade's fit build their view with.
LightSpace orthoLightSpace(const LightSettings& light, const glm::dvec3& direction, const glm::dvec3& eye,
                           double halfSize, double nearPlane, double farPlane);

struct CubeFace {
    const char* name;  // "+X"
    glm::dvec3 look;   // the face's axis: the direction its view looks along
    glm::dvec3 up;     // GL's up vector for the face
};
const std::array<CubeFace, 6>& cubeFaces();

// A point light's six views: 90-degree perspective faces in GL's cube-map order, each storing its own perspective
// depth (so polygon offset means what it means for a spot light), all sharing near/far (autoFit: near = far / 1000,
// far = the farthest point of the scene's bounding sphere, or the light's range if nearer).
std::optional<std::array<LightSpace, 6>> buildCubeFaceSpaces(const LightSettings& light, const Bounds& bounds,
                                                             const glm::dvec3& origin, std::string& error);

bool allFinite(const glm::dmat4& m);
bool allFinite(const glm::mat4& m);

}  // namespace shadowlab
