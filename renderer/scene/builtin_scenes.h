#pragma once
// Procedural scenes: no files needed. Y up, CCW outward winding, flat normals on planar faces (spheres carry their
// analytic, smooth normals), one Mesh per object, identity instance transforms (vertices are in world space) except
// the moving cars of "city-traffic", which their animation's nodes place.
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

// Every scene except "grazing" and "room": a floor quad at y = 0, centred at the origin, normal +y.
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

// "room": a closed box room (hard case 9, point-light cube seams). Floor, ceiling and four walls are single-sided
// quads (material "wall"; the floor keeps "floor") whose front faces look INTO the room: from the light inside they
// are front faces, and an outside camera sees through the near walls into the room (back faces are not drawn).
// The point light sits at the room's centre. The room is wider and deeper than it is high, and deeper than wide,
// so the cube map's face edges cross the floor, the ceiling and the long walls (in a cube room with the light at
// its centre every face edge would lie on a room edge): on the floor the -y face covers |x|, |z| <= kRoomLight.y
// (a 6 x 6 square), the side faces the rest, split by the diagonals |x| = |z|; on the walls x = +-5 the faces
// change at z = +-5. The pillar stands on the diagonal x = z, so its shadow wedge holds the diagonal seam and its
// edges cross the square's edges (floor and ceiling) and run onto the wall x = 5 across the seam at z = 5. The
// table's shadow straddles the square's edge x = -3. Both touch the floor (contact shadows).
inline constexpr glm::vec3 kRoomMin{-5.0f, 0.0f, -7.0f};
inline constexpr glm::vec3 kRoomMax{5.0f, 6.0f, 7.0f};
inline constexpr glm::vec3 kRoomLight{0.0f, 3.0f, 0.0f};  // the centre of the room
inline constexpr float kRoomLightRange = 10.0f;           // beyond the farthest corner (sqrt(5^2 + 3^2 + 7^2) = 9.11)
inline constexpr glm::vec3 kRoomPillarCenter{1.5f, 3.0f, 1.5f};
inline constexpr glm::vec3 kRoomPillarSize{0.6f, 6.0f, 0.6f};  // floor to ceiling
inline constexpr glm::vec3 kRoomTableCenter{-2.5f, 0.0f, -1.5f};  // centre of the table's footprint on the floor
inline constexpr glm::vec3 kRoomTableTopSize{2.0f, 0.1f, 1.2f};
inline constexpr float kRoomTableHeight = 0.85f;  // top of the table top
inline constexpr float kRoomTableLegSize = 0.08f;  // square legs, thin casters, inset by one leg size

// "courtyard": the 20 x 20 floor with four buildings around its edge and thin posts in the middle, lit by four
// lights (Scene::lights, in this order): a directional sun, two spot lights on the hall and the tower aimed into
// the courtyard, and a point-light lantern above the posts, just higher than their tops, so the posts throw long
// shadows outward onto the ground and the buildings' walls.
struct CourtyardBox {
    const char* name;
    glm::vec3 center;
    glm::vec3 size;
};
inline constexpr CourtyardBox kCourtyardBuildings[] = {
    {"hall", {-6.5f, 2.5f, -5.0f}, {5.0f, 5.0f, 8.0f}},
    {"tower", {-6.5f, 4.0f, 6.5f}, {4.0f, 8.0f, 4.0f}},  // far from the auto-framed camera: it hides nothing
    {"house", {6.0f, 2.0f, 5.0f}, {6.0f, 4.0f, 4.0f}},  // its roof above the lantern: never edge-on to it
    {"shed", {6.0f, 1.0f, -6.0f}, {3.0f, 2.0f, 3.0f}},
};
inline constexpr float kCourtyardPostHeight = 2.5f;
inline constexpr CourtyardBox kCourtyardPosts[] = {
    {"post-nw", {-1.5f, 0.5f * kCourtyardPostHeight, -1.5f}, {0.1f, kCourtyardPostHeight, 0.1f}},
    {"post-ne", {1.5f, 0.5f * kCourtyardPostHeight, -1.5f}, {0.1f, kCourtyardPostHeight, 0.1f}},
    {"post-sw", {-1.5f, 0.5f * kCourtyardPostHeight, 1.5f}, {0.1f, kCourtyardPostHeight, 0.1f}},
    {"post-se", {1.5f, 0.5f * kCourtyardPostHeight, 1.5f}, {0.1f, kCourtyardPostHeight, 0.1f}},
    {"post-thin", {0.0f, 0.5f * kCourtyardPostHeight, 3.0f}, {0.03f, kCourtyardPostHeight, 0.03f}},
};
inline constexpr glm::vec3 kCourtyardSunDir{-0.5f, -1.0f, -0.25f};  // travels toward -x, -z (not normalized)
inline constexpr glm::vec3 kCourtyardHallSpot{-3.5f, 5.5f, -3.0f};  // above the hall's inner corner
inline constexpr glm::vec3 kCourtyardHallSpotTarget{2.0f, 0.0f, 2.5f};
inline constexpr float kCourtyardHallSpotConeDeg = 60.0f;  // full cone
inline constexpr glm::vec3 kCourtyardTowerSpot{-4.0f, 7.5f, 4.0f};  // beside the tower's top
inline constexpr glm::vec3 kCourtyardTowerSpotTarget{2.5f, 0.0f, -1.5f};
inline constexpr float kCourtyardTowerSpotConeDeg = 45.0f;
inline constexpr float kCourtyardSpotRange = 20.0f;
inline constexpr glm::vec3 kCourtyardLantern{0.0f, 3.0f, 0.0f};  // 0.5 above the posts' tops
inline constexpr float kCourtyardLanternRange = 14.0f;           // reaches the buildings' walls

// "city": about 2 km of box buildings on a street grid, seen from eye height in a street, lit by a low sun. A
// 2048^2 map fitted to it has texels of 1.4 world units, wider than the street furniture near the eye (hard for a
// scene-fitted map; what cascades are for). The ground (material "floor") is a kCityGroundSize square at y = 0.
// kCityBlocks x kCityBlocks blocks, kCityBlockSize on a side, kCityStreetWidth of road between them: block (i, j)
// has its centre at ((i - (n - 1) / 2) * period, 0, (j - (n - 1) / 2) * period), so streets run along x = k * period
// and z = k * period. Each block is a sidewalk slab kCityCurbHeight high whose inner square (kCitySidewalkWidth in
// from its edge) is cut into 1-3 x 1-3 lots, one box building each; heights come from a fixed hash of the block and
// lot (the same city on every machine), taller toward the centre, some towers with a narrower top.
inline constexpr int kCityBlocks = 20;
inline constexpr float kCityBlockSize = 80.0f;
inline constexpr float kCityStreetWidth = 20.0f;
inline constexpr float kCityPeriod = kCityBlockSize + kCityStreetWidth;
static_assert(kCityBlocks % 2 == 0, "an even block count puts a street on x = 0, where the eye stands");
inline constexpr float kCitySidewalkWidth = 4.0f;
inline constexpr float kCityCurbHeight = 0.15f;
inline constexpr float kCityGroundSize = 2000.0f;  // the blocks reach +-990
inline constexpr float kCityMaxHeight = 160.0f;  // no building is taller (towers at the centre)
// The viewpoint (Scene::viewpoint): eye height on the road of the street x = 0, looking down it toward -z.
inline constexpr glm::vec3 kCityEye{-5.0f, 1.7f, 440.0f};
inline constexpr glm::vec3 kCityEyeTarget{-1.0f, 1.2f, 390.0f};
// Street furniture on both sidewalks of the street x = 0, along its whole length, each piece one box per mesh:
// lamp posts ("lamp-post" pole, "lamp-arm", "lamp-head") at block centre + kCityLampOffsets along z, kCityLampCurb
// in from the curb; benches ("bench-seat", "bench-back", "bench-leg") at block centre + kCityBenchOffset, facing the
// street; bollards ("bollard") in a row along the curb at each block corner.
inline constexpr float kCityLampOffsets[] = {-30.0f, 0.0f, 30.0f};
inline constexpr float kCityLampCurb = 0.6f;
inline constexpr float kCityLampHeight = 6.0f;  // above the sidewalk
inline constexpr float kCityLampPoleWidth = 0.16f;
inline constexpr float kCityBenchOffset = -34.0f;  // in view of the eye, clear of the bollards
inline constexpr float kCityBenchLength = 1.8f;
inline constexpr float kCityBenchSeatHeight = 0.45f;
inline constexpr int kCityBollardsPerCorner = 3;
inline constexpr float kCityBollardWidth = 0.2f;
inline constexpr float kCityBollardHeight = 0.9f;
// The sun (Scene::lights[0], directional): about 33 degrees above the horizon, behind the eye, shining down the street.
inline constexpr glm::vec3 kCitySunDir{-0.25f, -0.55f, -0.8f};  // travels toward -z (not normalized)

// "city-traffic": the same city (one generator) and kCityCars cars driving loops around blocks, played by one node
// animation "traffic" (the data a glTF file's animation gives: nodes "car-N" with a LINEAR translation channel and a
// STEP rotation channel each), every loop kCityTrafficSeconds long. Each car drives around a rectangle of street
// centre lines (builtin_scenes.cpp: kCityCarLoops), kCityLaneInset inside it (its inner lane, so no two loops share
// a lane); the rectangles do not overlap, so no two cars meet. Three cars are in the street x = 0 ahead of the eye.
inline constexpr int kCityCars = 6;
inline constexpr float kCityLaneInset = 3.5f;
inline constexpr float kCityTrafficSeconds = 60.0f;
// A car in its node's space: length along +z (its heading), standing on y = 0: a body clear of the road by
// kCityCarClearance (light passes under it). One box, so each built-in mesh stays one convex object (the scenes'
// validity test checks outward faces against the mesh's centre).
inline constexpr glm::vec3 kCityCarBody{1.8f, 1.5f, 4.2f};  // x, y, z size
inline constexpr float kCityCarClearance = 0.25f;

}  // namespace builtin
}  // namespace shadowlab
