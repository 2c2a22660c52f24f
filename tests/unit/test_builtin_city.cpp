// builtin:city (issue 20): about 2 km of buildings seen from eye height in a street, street furniture thinner than a
// scene-fitted map's texel near the eye, one low sun, the same city on every build, and a size llvmpipe handles.
#include "scene/builtin_scenes.h"
#include "scene/scene_animation.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace shadowlab;
namespace b = shadowlab::builtin;

namespace {

Scene city() {
    std::optional<Scene> scene = makeBuiltinScene("city");
    if (!scene) throw std::runtime_error("no builtin:city");
    return *scene;
}

Bounds meshBounds(const Mesh& mesh) {
    Bounds bounds;
    for (const glm::vec3& p : mesh.positions) bounds.extend(p);
    return bounds;
}

}  // namespace

TEST(BuiltinCity, IsAboutTwoKilometresAcrossWithStreetsAndVariedHeights) {
    const Scene s = city();
    const glm::vec3 size = s.bounds.max - s.bounds.min;
    EXPECT_NEAR(size.x, 2000.0f, 100.0f);
    EXPECT_NEAR(size.z, 2000.0f, 100.0f);
    EXPECT_GT(size.y, 60.0f);
    EXPECT_LE(size.y, b::kCityMaxHeight + b::kCityCurbHeight + 1e-3f);
    // The figure: a 2048^2 map fitted to the bounding sphere has texels of about 1.4 world units.
    EXPECT_NEAR(2.0f * s.bounds.radius() / 2048.0f, 1.4f, 0.05f);

    int buildings = 0;
    float lowest = 1e9f, highest = 0.0f;
    for (const Mesh& m : s.meshes) {
        if (m.name != "building" && m.name != "tower") continue;
        ++buildings;
        const Bounds mb = meshBounds(m);
        lowest = std::min(lowest, mb.max.y);
        highest = std::max(highest, mb.max.y);
        // Nothing stands on the streets: every building is inside its block's inner square.
        const float half = 0.5f * (b::kCityBlockSize - 2.0f * b::kCitySidewalkWidth);
        for (const float c : {mb.min.x, mb.max.x, mb.min.z, mb.max.z}) {
            const float fromBlockCentre = std::remainder(c - 0.5f * b::kCityPeriod, b::kCityPeriod);
            EXPECT_LE(std::abs(fromBlockCentre), half + 1e-2f) << m.name << " at " << c;
        }
    }
    EXPECT_GT(buildings, b::kCityBlocks * b::kCityBlocks);  // most blocks hold several lots
    EXPECT_GT(highest - lowest, 50.0f) << "heights vary";
    // Embree and llvmpipe handle it in seconds (measured: 640x360 in about a second).
    EXPECT_LT(s.triangleCount(), 100000u);
}

TEST(BuiltinCity, TheViewpointIsAtEyeHeightLookingDownAStreet) {
    const Scene s = city();
    ASSERT_TRUE(s.viewpoint.has_value());
    const glm::dvec3 eye = s.viewpoint->position, forward = glm::normalize(s.viewpoint->target - eye);
    EXPECT_NEAR(eye.y, 1.7, 1e-6);
    EXPECT_LT(std::abs(eye.x), 0.5 * b::kCityStreetWidth) << "on the road of the street x = 0";
    EXPECT_LT(forward.z, -0.95) << "down the street (toward -z)";
    EXPECT_LT(std::abs(forward.y), 0.1) << "level";
}

TEST(BuiltinCity, StreetFurnitureThinnerThanAFittedTexelStandsNearTheEye) {
    const Scene s = city();
    const glm::vec3 eye(s.viewpoint->position);
    const float texel = 2.0f * s.bounds.radius() / 2048.0f;
    std::map<std::string, int> near;  // pieces ahead of the eye within 40 m
    for (const Mesh& m : s.meshes) {
        const Bounds mb = meshBounds(m);
        const glm::vec3 c = mb.center();
        if (eye.z - c.z < 0.0f || glm::length(c - eye) > 40.0f) continue;
        ++near[m.name];
        if (m.name == "lamp-post" || m.name == "bollard") {
            EXPECT_LT(mb.max.x - mb.min.x, 0.2f * texel) << m.name;
            EXPECT_LT(mb.max.z - mb.min.z, 0.2f * texel) << m.name;
        }
    }
    EXPECT_GE(near["lamp-post"], 2);
    EXPECT_GE(near["lamp-head"], 2);
    EXPECT_GE(near["bench-seat"], 1);
    EXPECT_GE(near["bollard"], 3);
}

TEST(BuiltinCity, OneLowSunAndTheSameCityEveryTime) {
    const Scene s = city();
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, SceneLightType::Directional);
    const double elevation = glm::degrees(std::asin(-double(s.lights[0].direction.y)));
    EXPECT_GT(elevation, 20.0);
    EXPECT_LT(elevation, 45.0);
    const Scene again = city();
    ASSERT_EQ(again.meshes.size(), s.meshes.size());
    for (std::size_t i = 0; i < s.meshes.size(); ++i) ASSERT_EQ(again.meshes[i].positions, s.meshes[i].positions);
}

// builtin:city-traffic (issue 22): the same city from the same generator, and cars driving loops on its streets as
// a node animation (the data a glTF animation gives), never on a sidewalk, never meeting, back where they started
// after kCityTrafficSeconds.
namespace {

Scene cityTraffic() {
    std::optional<Scene> scene = makeBuiltinScene("city-traffic");
    if (!scene) throw std::runtime_error("no builtin:city-traffic");
    return *scene;
}

// Distance from v to the nearest street centre line k * period.
float offStreet(float v) { return std::abs(std::remainder(v, b::kCityPeriod)); }

}  // namespace

TEST(BuiltinCityTraffic, IsTheCityPlusCarsOnAnimatedNodes) {
    const Scene plain = city(), s = cityTraffic();
    EXPECT_TRUE(plain.animations.empty()) << "builtin:city itself holds still: its figures stand";
    ASSERT_EQ(s.meshes.size(), plain.meshes.size() + std::size_t(b::kCityCars));
    for (std::size_t i = 0; i < plain.meshes.size(); ++i) ASSERT_EQ(s.meshes[i].positions, plain.meshes[i].positions);
    ASSERT_EQ(s.animations.size(), 1u);
    const Animation& traffic = s.animations[0];
    EXPECT_EQ(traffic.name, "traffic");
    EXPECT_EQ(traffic.end, double(b::kCityTrafficSeconds));
    ASSERT_EQ(traffic.channels.size(), std::size_t(2 * b::kCityCars));
    ASSERT_EQ(s.nodes.size(), std::size_t(b::kCityCars));
    int cars = 0;
    for (const Instance& instance : s.instances) {
        if (instance.node < 0) continue;
        ++cars;
        EXPECT_EQ(s.meshes[std::size_t(instance.mesh)].name, "car");
        EXPECT_EQ(s.nodes[std::size_t(instance.node)].path, "car-" + std::to_string(s.nodes[std::size_t(instance.node)].gltfIndex));
    }
    EXPECT_EQ(cars, b::kCityCars);
    // The bounds hold every pose (each car as its bounding sphere: a little below the ground) and the whole city.
    for (int a = 0; a < 3; ++a) {
        EXPECT_LE(s.bounds.min[a], plain.bounds.min[a]);
        EXPECT_GE(s.bounds.max[a], plain.bounds.max[a]);
    }
    EXPECT_GT(s.bounds.min.y, -3.0f);
}

TEST(BuiltinCityTraffic, CarsDriveLoopsOnTheRoadNeverMeetAndComeBack) {
    Scene s = cityTraffic();
    const Scene start = s;
    const glm::dvec3 eye = s.viewpoint->position;
    int inFrontOfTheEye = 0;
    for (double t = 0.0; t <= double(b::kCityTrafficSeconds); t += 0.25) {
        poseScene(s, {0}, t);
        std::vector<glm::vec3> centres;
        for (const Instance& instance : s.instances) {
            if (instance.node < 0) continue;
            const Bounds local = meshBounds(s.meshes[std::size_t(instance.mesh)]);
            Bounds world;
            for (int c = 0; c < 8; ++c)
                world.extend(glm::vec3(instance.transform * glm::vec4(c & 1 ? local.max.x : local.min.x,
                                                                      c & 2 ? local.max.y : local.min.y,
                                                                      c & 4 ? local.max.z : local.min.z, 1.0f)));
            EXPECT_NEAR(world.min.y, b::kCityCarClearance, 1e-3f) << "t " << t;
            // On the road: every corner of its footprint inside a street, its centre on an inner lane.
            for (const float x : {world.min.x, world.max.x})
                for (const float z : {world.min.z, world.max.z})
                    EXPECT_LT(std::min(offStreet(x), offStreet(z)), 0.5f * b::kCityStreetWidth) << "t " << t;
            // Its centre on the inner lane across the way it heads (its +z).
            const glm::vec3 c = world.center(), heading(instance.transform[2]);
            const float across = std::abs(heading.x) > std::abs(heading.z) ? c.z : c.x;
            EXPECT_NEAR(offStreet(across), b::kCityLaneInset, 0.01f) << "t " << t;
            centres.push_back(c);
            inFrontOfTheEye += t == 0.0 && std::abs(c.x) < 10.0f && eye.z - c.z > 10.0 && eye.z - c.z < 250.0;
        }
        ASSERT_EQ(centres.size(), std::size_t(b::kCityCars));
        for (std::size_t i = 0; i < centres.size(); ++i)
            for (std::size_t j = i + 1; j < centres.size(); ++j)
                EXPECT_GT(glm::length(centres[i] - centres[j]), 5.0f) << "cars " << i << " and " << j << " at t " << t;
    }
    EXPECT_EQ(inFrontOfTheEye, 3) << "three cars in the street ahead of the eye at t = 0";
    // A loop ends where it began, heading the same way.
    for (std::size_t i = 0; i < s.instances.size(); ++i)
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 4; ++row)
                EXPECT_NEAR(s.instances[i].transform[col][row], start.instances[i].transform[col][row], 1e-3f);
}

TEST(BuiltinCityTraffic, ACarHeadsWhereItDrives) {
    Scene s = cityTraffic();
    Scene later = s;
    int checked = 0;
    for (double t = 0.3; t < double(b::kCityTrafficSeconds); t += 1.7) {
        poseScene(s, {0}, t);
        poseScene(later, {0}, t + 0.05);
        for (std::size_t i = 0; i < s.instances.size(); ++i) {
            if (s.instances[i].node < 0) continue;
            const glm::vec3 moved = glm::vec3(later.instances[i].transform[3] - s.instances[i].transform[3]);
            const glm::vec3 heading = glm::normalize(glm::vec3(s.instances[i].transform[2]));  // the car's +z
            if (glm::length(moved) < 1e-4f || glm::dot(glm::normalize(moved), heading) < 0.5f) {
                // Only across a corner (a STEP turn) may the step and the heading disagree.
                EXPECT_LT(std::min(offStreet(s.instances[i].transform[3].x), offStreet(s.instances[i].transform[3].z)) +
                              std::max(offStreet(s.instances[i].transform[3].x), offStreet(s.instances[i].transform[3].z)),
                          2.0f * b::kCityLaneInset + 1.0f)
                    << "car " << i << " at t " << t;
                continue;
            }
            EXPECT_GT(glm::dot(glm::normalize(moved), heading), 0.999f) << "car " << i << " at t " << t;
            ++checked;
        }
    }
    EXPECT_GT(checked, 150);
}
