#pragma once
// Procedural scenes: no files needed. Y up, CCW outward winding, flat normals on planar faces (spheres carry their
// analytic, smooth normals), one Mesh per object, identity instance transforms (vertices are in world space).
// The constants below are the exact dimensions, so tests can compute by hand where shadows fall.
#include "scene/scene.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

std::vector<std::string> builtinSceneNames();                    // "textbook" first (the default scene)
std::string builtinSceneDescription(const std::string& name);    // empty for an unknown name
std::optional<Scene> makeBuiltinScene(const std::string& name);  // nullopt for an unknown name

namespace builtin {

// Every scene except "grazing": a floor quad at y = 0, centred at the origin, normal +y.
inline constexpr float kFloorSize = 20.0f;  // 20 x 20

// The default light of Settings (direction the light travels, not normalized); "grazing" is built against it.
inline constexpr glm::vec3 kDefaultLightDir{-0.4f, -1.0f, -0.3f};

// "textbook"
inline constexpr glm::vec3 kCubeCenter{0.0f, 1.0f, 0.0f};
inline constexpr float kCubeSize = 2.0f;                         // 2 x 2 x 2, resting on the floor
inline constexpr glm::vec3 kTextbookSphereCenter{-4.0f, 1.0f, 3.0f};
inline constexpr float kTextbookSphereRadius = 1.0f;             // resting on the floor
inline constexpr int kTextbookSphereSegments = 64;               // longitude x latitude
inline constexpr int kTextbookSphereRings = 32;
inline constexpr glm::vec3 kFloatingBoxCenter{4.0f, 3.0f, -3.0f};
inline constexpr glm::vec3 kFloatingBoxSize{1.5f, 0.5f, 1.5f};   // bottom at y = 2.75: its shadow is detached

// "grazing": a 40 x 40 plane through the origin whose normal makes kGrazingAngleDeg with -kDefaultLightDir,
// tilted as little as possible from horizontal (about 53.4 deg, away from the light). A unit box rests on it.
inline constexpr float kGrazingPlaneSize = 40.0f;
inline constexpr float kGrazingAngleDeg = 80.0f;
inline constexpr float kGrazingBoxSize = 1.0f;  // centred at kGrazingBoxSize/2 * normal (its bottom face on the plane)
glm::vec3 grazingPlaneNormal();                  // unit; dot(n, -normalize(kDefaultLightDir)) = cos(80 deg)

// "thin-walls": three walls along x (x in [-3, 3]), standing on the floor, thickness along z.
inline constexpr int kThinWallCount = 3;
inline constexpr float kThinWallThickness[kThinWallCount] = {0.02f, 0.1f, 0.5f};
inline constexpr float kThinWallCenterZ[kThinWallCount] = {-4.0f, 0.0f, 4.0f};
inline constexpr float kThinWallHeight = 3.0f;
inline constexpr float kThinWallLength = 6.0f;

// "fence": a double-sided quad in the plane z = 0, x in [kFenceXMin, kFenceXMax], y in [0, kFenceHeight],
// alphaMode MASK, cutoff 0.5, texture kFenceImageWidth x kFenceImageHeight, u = (x - xMin) / width,
// v = (height - y) / height (glTF: v = 0 is the top row of the image).
// Slat k (0..kFenceSlatCount-1) is opaque for x in [xMin + k*period + slatStart, ... + slatWidth); the rest of each
// period is a gap (alpha 0), except the horizontal rail y in [kFenceRailYMin, kFenceRailYMax], opaque everywhere.
// All edges fall on texel boundaries (32 texels per period, 16 per slat, rail = rows 16..23).
inline constexpr float kFenceXMin = -4.0f;
inline constexpr float kFenceXMax = 4.0f;
inline constexpr float kFenceHeight = 3.0f;
inline constexpr int kFenceSlatCount = 8;
inline constexpr float kFenceSlatPeriod = 1.0f;
inline constexpr float kFenceSlatStart = 0.25f;  // slat offset inside its period: gaps at both fence ends
inline constexpr float kFenceSlatWidth = 0.5f;
inline constexpr float kFenceRailYMin = 1.875f;
inline constexpr float kFenceRailYMax = 2.25f;
inline constexpr int kFenceImageWidth = 256;
inline constexpr int kFenceImageHeight = 64;
inline constexpr float kFenceAlphaCutoff = 0.5f;

// True where the fence texture is opaque at fence-plane coordinates (x, y) (false outside the quad).
inline bool fenceOpaqueAt(float x, float y) {
    if (x < kFenceXMin || x > kFenceXMax || y < 0.0f || y > kFenceHeight) return false;
    if (y >= kFenceRailYMin && y <= kFenceRailYMax) return true;
    const float inPeriod = std::fmod(x - kFenceXMin, kFenceSlatPeriod);
    return inPeriod >= kFenceSlatStart && inPeriod < kFenceSlatStart + kFenceSlatWidth;
}

// Exact shadow test for a point p under a directional light travelling along lightDir: does the ray from p toward
// the light cross the fence where it is opaque? (The floor and the fence are the only geometry of the scene.)
inline bool fenceShadowsPoint(const glm::vec3& p, const glm::vec3& lightDir) {
    const glm::vec3 toLight = -lightDir;
    if (std::abs(toLight.z) < 1e-12f) return false;  // ray parallel to the fence plane
    const float t = -p.z / toLight.z;
    if (t <= 0.0f) return false;  // the fence is behind the point, away from the light
    const glm::vec3 hit = p + t * toLight;
    return fenceOpaqueAt(hit.x, hit.y);
}

// "sphere-plane": the analytic check scene.
inline constexpr glm::vec3 kSpherePlaneCenter{0.0f, 2.0f, 0.0f};
inline constexpr float kSpherePlaneRadius = 1.0f;
inline constexpr int kSpherePlaneSegments = 128;
inline constexpr int kSpherePlaneRings = 64;

// "roof": a single-sided square (material "roof", not doubleSided) at height kRoofHeight whose front face looks
// DOWN (-y), above the floor, lit from above: seen from the light it is a back face, so a shadow pass that culls
// back faces drops it while the exact reference (every triangle blocks) keeps its shadow. A closed box beside it.
inline constexpr glm::vec3 kRoofCenter{0.0f, 3.0f, 0.0f};
inline constexpr float kRoofSize = 6.0f;  // 6 x 6
inline constexpr glm::vec3 kRoofBoxCenter{5.0f, 0.75f, -4.0f};
inline constexpr float kRoofBoxSize = 1.5f;

}  // namespace builtin
}  // namespace shadowlab
