// The built-ins that carry their own lights: "room" (a point light in a closed room whose cube-map seams cross the
// floor and walls, hard case 9) and "courtyard" (a sun, two spots and a point light). Checked with a small
// double-precision ray caster over the scene's triangles: the room is closed around its light, and the pillar's
// shadow falls on both sides of the cube faces' edges.
#include "light/scene_lights.h"
#include "scene/builtin_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/common.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vector_relational.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <set>

using namespace shadowlab;
namespace b = shadowlab::builtin;

namespace {

Scene builtinOrDie(const std::string& name) {
    std::optional<Scene> scene = makeBuiltinScene(name);
    if (!scene) throw std::runtime_error("no builtin " + name);
    return *scene;
}

struct Hit {
    double t = 0.0;
    glm::dvec3 normal{0.0};  // the triangle's geometric (winding) normal, unit
    std::string mesh;
};

// Nearest triangle the ray origin + t * dir (t > tMin) hits, both sides counted (the reference's rule: every
// triangle blocks). Builtin instances are identities, so mesh positions are world positions.
std::optional<Hit> castRay(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& dir, double tMin = 1e-9) {
    std::optional<Hit> best;
    for (const Mesh& mesh : scene.meshes) {
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const glm::dvec3 a(mesh.positions[mesh.indices[i]]), bb(mesh.positions[mesh.indices[i + 1]]),
                c(mesh.positions[mesh.indices[i + 2]]);
            const glm::dvec3 e1 = bb - a, e2 = c - a, p = glm::cross(dir, e2);
            const double det = glm::dot(e1, p);
            if (std::abs(det) < 1e-14) continue;
            const glm::dvec3 s = origin - a;
            const double u = glm::dot(s, p) / det;
            const glm::dvec3 q = glm::cross(s, e1);
            const double v = glm::dot(dir, q) / det;
            const double t = glm::dot(e2, q) / det;
            // A small tolerance so that rays through a shared edge or corner still hit one of its triangles.
            if (u < -1e-9 || v < -1e-9 || u + v > 1.0 + 1e-9 || t <= tMin) continue;
            if (!best || t < best->t) best = Hit{t, glm::normalize(glm::cross(e1, e2)), mesh.name};
        }
    }
    return best;
}

// Whether the segment from p to the light is blocked (p on a surface: start a hair off it, stop before the light).
bool shadowedFrom(const Scene& scene, const glm::dvec3& p, const glm::dvec3& light) {
    const glm::dvec3 d = light - p;
    const double length = glm::length(d);
    const std::optional<Hit> hit = castRay(scene, p, d / length, 1e-6);
    return hit && hit->t < length - 1e-6;
}

// The cube face a direction from a point light falls in, as in GL's cube map selection: the major axis (0..2) and
// its sign, 0..5 = +x, -x, +y, -y, +z, -z.
int cubeFace(const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    return 2 * axis + (d[axis] < 0.0 ? 1 : 0);
}

// Unit directions spread evenly over the sphere (Fibonacci lattice).
std::vector<glm::dvec3> sphereDirections(int count) {
    std::vector<glm::dvec3> dirs;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count, r = std::sqrt(1.0 - y * y), phi = golden * i;
        dirs.emplace_back(r * std::cos(phi), y, r * std::sin(phi));
    }
    return dirs;
}

// The lights a frame uses with useSceneLights on.
std::vector<LightSettings> sceneLightsOf(const Scene& scene) {
    Settings settings;
    settings.useSceneLights = true;
    return effectiveLights(settings, scene);
}

const SceneLight& onlyLight(const Scene& scene) {
    if (scene.lights.size() != 1) throw std::runtime_error("expected one light");
    return scene.lights[0];
}

}  // namespace

TEST(RoomScene, OnePointLightAtTheCentreWhoseRangeReachesEveryCorner) {
    const Scene room = builtinOrDie("room");
    ASSERT_EQ(room.lights.size(), 1u);
    const SceneLight& bulb = onlyLight(room);
    EXPECT_EQ(bulb.type, SceneLightType::Point);
    EXPECT_EQ(bulb.position, b::kRoomLight);
    EXPECT_EQ(bulb.position, 0.5f * (b::kRoomMin + b::kRoomMax));
    // The room's bounds are its walls: nothing sticks out.
    EXPECT_EQ(room.bounds.min, b::kRoomMin);
    EXPECT_EQ(room.bounds.max, b::kRoomMax);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 c((corner & 1) ? b::kRoomMax.x : b::kRoomMin.x, (corner & 2) ? b::kRoomMax.y : b::kRoomMin.y,
                          (corner & 4) ? b::kRoomMax.z : b::kRoomMin.z);
        EXPECT_LT(glm::length(c - bulb.position), bulb.range) << "corner " << corner;
    }
    // useSceneLights brings it in as a point light with its range.
    const std::vector<LightSettings> lights = sceneLightsOf(room);
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_EQ(lights[0].type, LightType::Point);
    EXPECT_EQ(lights[0].position, b::kRoomLight);
    EXPECT_EQ(lights[0].range, b::kRoomLightRange);
}

// A ray from the light in any direction meets the room's inside: a wall, the floor, the ceiling, the pillar or the
// table, always within the light's range, and every room surface it meets faces the light (single-sided quads whose
// front faces look into the room). Directions on the cube map's face edges and corners included.
TEST(RoomScene, ClosedAroundTheLightWithEveryWallFacingIt) {
    const Scene room = builtinOrDie("room");
    const glm::dvec3 light(onlyLight(room).position);
    std::vector<glm::dvec3> dirs = sphereDirections(4000);
    for (int sx : {-1, 1})
        for (int sy : {-1, 1})
            for (int sz : {-1, 1}) {
                dirs.push_back(glm::normalize(glm::dvec3(sx, sy, sz)));  // cube corners: |x| = |y| = |z|
                dirs.push_back(glm::normalize(glm::dvec3(sx, sy, 0)));   // face edges: |major| = |minor|
                dirs.push_back(glm::normalize(glm::dvec3(sx, 0, sz)));
                dirs.push_back(glm::normalize(glm::dvec3(0, sy, sz)));
            }
    std::set<std::string> met;
    int missed = 0, backFacing = 0, outOfRange = 0;
    for (const glm::dvec3& d : dirs) {
        const std::optional<Hit> hit = castRay(room, light, d);
        if (!hit) {
            ++missed;
            continue;
        }
        met.insert(hit->mesh);
        outOfRange += hit->t > double(b::kRoomLightRange);
        backFacing += glm::dot(hit->normal, d) >= 0.0;
    }
    EXPECT_EQ(missed, 0) << "rays from the light that leave the room";
    EXPECT_EQ(outOfRange, 0);
    EXPECT_EQ(backFacing, 0) << "surfaces the light sees from behind";
    for (const char* surface : {"floor", "ceiling", "wall+x", "wall-x", "wall+z", "wall-z", "pillar", "table-top"})
        EXPECT_TRUE(met.count(surface)) << surface << " is never seen from the light";
}

// Hard case 9 needs shadows across the cube faces' edges: the pillar's shadow (exact, by ray casting) covers floor
// points in the -y face and in the side faces, on both sides of the diagonal seam |x| = |z|, and reaches the wall
// x = +5 on both sides of its seam z = 5; the table's shadow straddles the floor seam x = -3.
TEST(RoomScene, ShadowsCrossTheCubeMapSeams) {
    const Scene room = builtinOrDie("room");
    const glm::dvec3 light(onlyLight(room).position);
    std::set<int> floorFaces;
    int diagonalBelow = 0, diagonalAbove = 0, tableNear = 0, tableFar = 0;
    for (double x = -4.95; x < 5.0; x += 0.1) {
        for (double z = -6.95; z < 7.0; z += 0.1) {
            const glm::dvec3 p(x, 0.0, z);
            if (!shadowedFrom(room, p, light)) continue;
            const int face = cubeFace(p - light);
            if (x > 0.0 && z > 0.0) {  // the pillar's quadrant
                floorFaces.insert(face);
                (z < x ? diagonalBelow : diagonalAbove) += face != 3;  // beyond the -y face, either side of |x| = |z|
            }
            if (x < 0.0 && z < 0.0 && z > -3.0) (x < -light.y ? tableFar : tableNear)++;  // the seam x = -3
        }
    }
    EXPECT_TRUE(floorFaces.count(3)) << "the pillar's shadow in the floor's own face (-y)";
    EXPECT_TRUE(floorFaces.count(0)) << "... and in +x";
    EXPECT_TRUE(floorFaces.count(4)) << "... and in +z";
    EXPECT_GT(diagonalBelow, 10);
    EXPECT_GT(diagonalAbove, 10);
    EXPECT_GT(tableNear, 10);
    EXPECT_GT(tableFar, 10);

    // The wall x = +5, at mid height: the shadow lies across its seam z = 5 (faces +x and +z).
    std::set<int> wallFaces;
    for (double z = 0.05; z < 7.0; z += 0.1) {
        const glm::dvec3 p(b::kRoomMax.x, 1.0, z);
        if (shadowedFrom(room, p, light)) wallFaces.insert(cubeFace(p - light));
    }
    EXPECT_TRUE(wallFaces.count(0));
    EXPECT_TRUE(wallFaces.count(4));
    // And a lit control: the floor point straight below the light and the opposite corner's quadrant.
    EXPECT_FALSE(shadowedFrom(room, {0.0, 0.0, 0.0}, light));
    EXPECT_FALSE(shadowedFrom(room, {-2.5, 0.0, 4.0}, light));
}

TEST(CourtyardScene, ASunTwoSpotsAndALanternOverBuildingsAndThinPosts) {
    const Scene yard = builtinOrDie("courtyard");
    ASSERT_EQ(yard.lights.size(), 4u);
    const SceneLight &sun = yard.lights[0], &hallSpot = yard.lights[1], &towerSpot = yard.lights[2],
                     &lantern = yard.lights[3];
    EXPECT_EQ(sun.type, SceneLightType::Directional);
    EXPECT_NEAR(glm::length(sun.direction), 1.0f, 1e-6f);
    EXPECT_LT(sun.direction.y, -0.5f) << "the sun shines down";
    EXPECT_EQ(hallSpot.type, SceneLightType::Spot);
    EXPECT_EQ(towerSpot.type, SceneLightType::Spot);
    EXPECT_EQ(lantern.type, SceneLightType::Point);

    // The floor and the tower's top bound the scene.
    EXPECT_EQ(yard.bounds.min, glm::vec3(-10.0f, 0.0f, -10.0f));
    EXPECT_EQ(yard.bounds.max, glm::vec3(10.0f, 8.0f, 10.0f));

    auto insideABuilding = [](const glm::vec3& p) {
        for (const b::CourtyardBox& box : b::kCourtyardBuildings)
            if (glm::all(glm::lessThanEqual(glm::abs(p - box.center), 0.5f * box.size))) return true;
        return false;
    };
    // Spots: above the ground, outside the buildings, aimed at their targets, which lie inside the courtyard and
    // within range; the target is lit by its spot (nothing in between).
    const std::pair<const SceneLight*, glm::vec3> spots[] = {{&hallSpot, b::kCourtyardHallSpotTarget},
                                                             {&towerSpot, b::kCourtyardTowerSpotTarget}};
    for (const auto& [spot, target] : spots) {
        SCOPED_TRACE(spot->name);
        EXPECT_GT(spot->position.y, 4.0f);
        EXPECT_FALSE(insideABuilding(spot->position));
        EXPECT_NEAR(glm::length(spot->direction), 1.0f, 1e-6f);
        EXPECT_GT(glm::dot(spot->direction, glm::normalize(target - spot->position)), 0.99999f);
        EXPECT_GT(spot->range, glm::length(target - spot->position));
        EXPECT_GT(spot->outerConeRad, glm::radians(15.0f));
        EXPECT_LT(spot->outerConeRad, glm::radians(45.0f));
        EXPECT_FALSE(shadowedFrom(yard, glm::dvec3(target), glm::dvec3(spot->position)));
    }
    // The lantern hangs above the posts' tops, outside every building, and its range reaches a building wall.
    EXPECT_GT(lantern.position.y, b::kCourtyardPostHeight);
    EXPECT_FALSE(insideABuilding(lantern.position));
    double nearestWall = 1e9;
    for (const b::CourtyardBox& box : b::kCourtyardBuildings) {
        const glm::vec3 gap = glm::max(glm::abs(lantern.position - box.center) - 0.5f * box.size, glm::vec3(0.0f));
        nearestWall = std::min(nearestWall, double(glm::length(gap)));
    }
    EXPECT_LT(nearestWall, lantern.range);

    // Thin posts: every post's shadow under the lantern runs outward past its foot (exact: the point just beyond
    // the foot, away from the lantern, is shadowed; the point on the lantern's side is not).
    for (const b::CourtyardBox& post : b::kCourtyardPosts) {
        SCOPED_TRACE(post.name);
        EXPECT_LE(std::max(post.size.x, post.size.z), 0.1f);
        const glm::dvec3 foot(post.center.x, 0.0, post.center.z);
        const glm::dvec3 outward = glm::normalize(foot - glm::dvec3(lantern.position.x, 0.0, lantern.position.z));
        const glm::dvec3 lamp(lantern.position);
        EXPECT_TRUE(shadowedFrom(yard, foot + outward * 1.0, lamp));
        EXPECT_FALSE(shadowedFrom(yard, foot - outward * 1.0, lamp));
    }

    const std::vector<LightSettings> lights = sceneLightsOf(yard);
    ASSERT_EQ(lights.size(), 4u);
    EXPECT_EQ(lights[0].type, LightType::Directional);
    EXPECT_EQ(lights[1].type, LightType::Spot);
    EXPECT_NEAR(lights[1].spotConeDeg, b::kCourtyardHallSpotConeDeg, 1e-4f);
    EXPECT_EQ(lights[2].type, LightType::Spot);
    EXPECT_NEAR(lights[2].spotConeDeg, b::kCourtyardTowerSpotConeDeg, 1e-4f);
    EXPECT_EQ(lights[3].type, LightType::Point);
    EXPECT_EQ(lights[3].range, b::kCourtyardLanternRange);
}
