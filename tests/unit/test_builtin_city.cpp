// builtin:city (issue 20): about 2 km of buildings seen from eye height in a street, street furniture thinner than a
// scene-fitted map's texel near the eye, one low sun, the same city on every build, and a size llvmpipe handles.
#include "scene/builtin_scenes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <map>
#include <string>

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
