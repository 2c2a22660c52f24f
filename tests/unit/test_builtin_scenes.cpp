// Built-in scenes: they load, are valid, face outward, and match the constants the GL tests compute shadows from.
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

using namespace shadowlab;
namespace b = shadowlab::builtin;

namespace {

const Mesh* meshNamed(const Scene& scene, const std::string& name) {
    for (const Mesh& m : scene.meshes)
        if (m.name == name) return &m;
    return nullptr;
}

Bounds meshBounds(const Mesh& mesh) {
    Bounds bounds;
    for (const glm::vec3& p : mesh.positions) bounds.extend(p);
    return bounds;
}

void expectVecNear(const glm::vec3& a, const glm::vec3& e, float tol) {
    EXPECT_NEAR(a.x, e.x, tol);
    EXPECT_NEAR(a.y, e.y, tol);
    EXPECT_NEAR(a.z, e.z, tol);
}

Scene builtinOrDie(const std::string& name) {
    std::optional<Scene> scene = makeBuiltinScene(name);
    if (!scene) throw std::runtime_error("no builtin " + name);
    return *scene;
}

}  // namespace

TEST(BuiltinScenes, NamesDescriptionsAndDefault) {
    const std::vector<std::string> names = builtinSceneNames();
    ASSERT_EQ(names.size(), 10u);  // city-traffic is the tenth
    EXPECT_EQ(names.front(), "textbook");
    EXPECT_EQ(std::string(kDefaultSceneSpec), "builtin:textbook");
    for (const std::string& n : names) EXPECT_FALSE(builtinSceneDescription(n).empty()) << n;
    EXPECT_TRUE(builtinSceneDescription("nope").empty());
    EXPECT_FALSE(makeBuiltinScene("nope").has_value());
}

// The roof: one single-sided square whose front face (CCW winding and its normal) looks down, above the floor.
TEST(BuiltinScenes, RoofIsASingleSidedSquareFacingDown) {
    const std::optional<Scene> scene = makeBuiltinScene("roof");
    ASSERT_TRUE(scene.has_value());
    const auto roof = std::find_if(scene->meshes.begin(), scene->meshes.end(),
                                   [](const Mesh& m) { return m.name == "roof"; });
    ASSERT_NE(roof, scene->meshes.end());
    const Material* material = scene->materialOf(*roof);
    ASSERT_NE(material, nullptr);
    EXPECT_FALSE(material->doubleSided);
    ASSERT_EQ(roof->triangleCount(), 2u);
    for (std::size_t t = 0; t < roof->triangleCount(); ++t) {
        const glm::vec3 a = roof->positions[roof->indices[3 * t]], b = roof->positions[roof->indices[3 * t + 1]],
                        c = roof->positions[roof->indices[3 * t + 2]];
        EXPECT_LT(glm::cross(b - a, c - a).y, 0.0f) << "the winding's front looks down";
        EXPECT_FLOAT_EQ(a.y, builtin::kRoofCenter.y);
    }
    for (const glm::vec3& n : roof->normals) EXPECT_FLOAT_EQ(n.y, -1.0f);
}

TEST(BuiltinScenes, EveryBuiltinIsValidWithFiniteBoundsAndOutwardNormals) {
    for (const std::string& name : builtinSceneNames()) {
        SCOPED_TRACE(name);
        const SceneLoadResult r = loadScene(std::string(kBuiltinPrefix) + name);
        ASSERT_TRUE(r.ok()) << r.error;
        const Scene& scene = *r.scene;
        EXPECT_EQ(scene.name, name);
        EXPECT_EQ(scene.invariantError(), "");
        EXPECT_TRUE(scene.warnings.empty());
        EXPECT_FALSE(scene.bounds.empty);
        EXPECT_TRUE(std::isfinite(scene.bounds.radius()) && scene.bounds.radius() > 1.0f);
        EXPECT_GT(scene.triangleCount(), 0u);
        for (const Instance& inst : scene.instances) EXPECT_FALSE(inst.mirrored());

        // Each mesh is one convex object or one planar quad: every face must look away from the mesh centroid,
        // agree with its vertex normals, and have non-zero area.
        for (const Mesh& mesh : scene.meshes) {
            SCOPED_TRACE(mesh.name);
            glm::dvec3 centroid(0.0);
            for (const glm::vec3& p : mesh.positions) centroid += glm::dvec3(p);
            centroid /= double(mesh.positions.size());
            int bad = 0;
            for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
                const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
                const glm::dvec3 a(mesh.positions[i0]), bb(mesh.positions[i1]), c(mesh.positions[i2]);
                const glm::dvec3 n = glm::cross(bb - a, c - a);
                const glm::dvec3 vn = glm::dvec3(mesh.normals[i0] + mesh.normals[i1] + mesh.normals[i2]);
                if (glm::length(n) <= 1e-12 || glm::dot(n, vn) <= 0.0 ||
                    glm::dot(glm::normalize(n), (a + bb + c) / 3.0 - centroid) < -1e-4)
                    ++bad;
            }
            EXPECT_EQ(bad, 0);
        }
    }
}

TEST(BuiltinScenes, UnknownBuiltinListsTheNames) {
    const SceneLoadResult r = loadScene("builtin:teapot");
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("teapot"), std::string::npos) << r.error;
    for (const std::string& n : builtinSceneNames()) EXPECT_NE(r.error.find(n), std::string::npos) << r.error;
}

TEST(BuiltinScenes, TextbookDimensions) {
    const Scene s = builtinOrDie("textbook");
    const Mesh* floor = meshNamed(s, "floor");
    ASSERT_NE(floor, nullptr);
    const Bounds fb = meshBounds(*floor);
    expectVecNear(fb.min, {-10, 0, -10}, 1e-6f);
    expectVecNear(fb.max, {10, 0, 10}, 1e-6f);
    for (const glm::vec3& n : floor->normals) expectVecNear(n, {0, 1, 0}, 1e-6f);

    const Bounds cube = meshBounds(*meshNamed(s, "cube"));
    expectVecNear(cube.min, {-1, 0, -1}, 1e-6f);
    expectVecNear(cube.max, {1, 2, 1}, 1e-6f);

    const Mesh* sphere = meshNamed(s, "sphere");
    ASSERT_NE(sphere, nullptr);
    for (const glm::vec3& p : sphere->positions)
        EXPECT_NEAR(glm::length(p - b::kTextbookSphereCenter), b::kTextbookSphereRadius, 1e-5f);
    EXPECT_NEAR(meshBounds(*sphere).min.y, 0.0f, 1e-5f);  // resting on the floor

    const Bounds box = meshBounds(*meshNamed(s, "floating-box"));
    expectVecNear(box.min, {3.25f, 2.75f, -3.75f}, 1e-6f);
    expectVecNear(box.max, {4.75f, 3.25f, -2.25f}, 1e-6f);
    expectVecNear(s.bounds.max, {10, 3.25f, 10}, 1e-6f);
}

TEST(BuiltinScenes, GrazingPlaneIsAt80DegreesToTheDefaultLight) {
    const glm::vec3 n = b::grazingPlaneNormal();
    const glm::vec3 toLight = -glm::normalize(b::kDefaultLightDir);
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(n, toLight), std::cos(glm::radians(80.0f)), 1e-5f);
    EXPECT_GT(n.y, 0.5f);  // faces up: the visible, lit side

    const Scene s = builtinOrDie("grazing");
    const Mesh* plane = meshNamed(s, "plane");
    ASSERT_NE(plane, nullptr);
    for (std::size_t i = 0; i < plane->positions.size(); ++i) {
        EXPECT_NEAR(glm::dot(plane->positions[i], n), 0.0f, 1e-5f);  // through the origin
        expectVecNear(plane->normals[i], n, 1e-6f);
    }
    EXPECT_NEAR(glm::length(plane->positions[0] - plane->positions[2]), 40.0f * std::sqrt(2.0f), 1e-3f);
    // The box sits on the plane: its lowest point (along n) is on it, its highest 1 above.
    const Mesh* box = meshNamed(s, "box");
    ASSERT_NE(box, nullptr);
    float lo = 1e9f, hi = -1e9f;
    for (const glm::vec3& p : box->positions) {
        lo = std::min(lo, glm::dot(p, n));
        hi = std::max(hi, glm::dot(p, n));
    }
    EXPECT_NEAR(lo, 0.0f, 1e-5f);
    EXPECT_NEAR(hi, b::kGrazingBoxSize, 1e-5f);
}

TEST(BuiltinScenes, ThinWallsHaveTheirThickness) {
    const Scene s = builtinOrDie("thin-walls");
    int walls = 0;
    for (const Mesh& m : s.meshes) {
        if (m.name.rfind("wall", 0) != 0) continue;
        const Bounds bb = meshBounds(m);
        const int i = walls++;
        ASSERT_LT(i, b::kThinWallCount);
        EXPECT_NEAR(bb.max.z - bb.min.z, b::kThinWallThickness[i], 1e-6f);
        EXPECT_NEAR(bb.center().z, b::kThinWallCenterZ[i], 1e-6f);
        EXPECT_NEAR(bb.min.y, 0.0f, 1e-6f);
        EXPECT_NEAR(bb.max.y, b::kThinWallHeight, 1e-6f);
        EXPECT_NEAR(bb.max.x - bb.min.x, b::kThinWallLength, 1e-6f);
    }
    EXPECT_EQ(walls, b::kThinWallCount);
}

TEST(BuiltinScenes, FenceTextureMatchesTheSlatConstants) {
    const Scene s = builtinOrDie("fence");
    EXPECT_TRUE(s.hasAlphaMaskedCasters());
    const Mesh* fence = meshNamed(s, "fence");
    ASSERT_NE(fence, nullptr);
    const Material* m = s.materialOf(*fence);
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m->alphaCutoff, 0.5f);
    EXPECT_TRUE(m->doubleSided);
    ASSERT_GE(m->baseColorImage, 0);
    const Image& img = s.images[std::size_t(m->baseColorImage)];
    ASSERT_TRUE(img.valid());
    EXPECT_EQ(img.width, 256);
    EXPECT_EQ(img.height, 64);
    ASSERT_EQ(fence->uvs.size(), fence->positions.size());

    // Sample the texture (nearest) at the uv the mesh gives a world point, and compare with fenceOpaqueAt.
    auto alphaAt = [&](float x, float y) {
        const float u = (x - b::kFenceXMin) / (b::kFenceXMax - b::kFenceXMin), v = (b::kFenceHeight - y) / b::kFenceHeight;
        const int col = std::min(int(u * float(img.width)), img.width - 1), row = std::min(int(v * float(img.height)), img.height - 1);
        return img.rgba[(std::size_t(row) * std::size_t(img.width) + std::size_t(col)) * 4 + 3];
    };
    // The mesh's uvs follow the documented mapping.
    for (std::size_t i = 0; i < fence->positions.size(); ++i) {
        const glm::vec3& p = fence->positions[i];
        EXPECT_NEAR(fence->uvs[i].x, (p.x - b::kFenceXMin) / (b::kFenceXMax - b::kFenceXMin), 1e-6f);
        EXPECT_NEAR(fence->uvs[i].y, (b::kFenceHeight - p.y) / b::kFenceHeight, 1e-6f);
        EXPECT_NEAR(p.z, 0.0f, 1e-7f);
    }
    int slats = 0, gaps = 0;
    for (float x = b::kFenceXMin + 0.01f; x < b::kFenceXMax; x += 0.0625f) {
        for (float y : {0.5f, 1.0f, 2.0f, 2.8f}) {
            const bool opaque = b::fenceOpaqueAt(x, y);
            EXPECT_EQ(alphaAt(x, y), opaque ? 255 : 0) << x << "," << y;
            (opaque ? slats : gaps)++;
        }
    }
    EXPECT_GT(slats, 0);
    EXPECT_GT(gaps, 0);
    // Slat centres and gap centres, below the rail; the rail is opaque across a gap.
    for (int k = 0; k < b::kFenceSlatCount; ++k) {
        const float x0 = b::kFenceXMin + float(k) * b::kFenceSlatPeriod;
        EXPECT_TRUE(b::fenceOpaqueAt(x0 + b::kFenceSlatStart + 0.5f * b::kFenceSlatWidth, 1.0f));
        EXPECT_FALSE(b::fenceOpaqueAt(x0 + 0.1f, 1.0f));
        EXPECT_TRUE(b::fenceOpaqueAt(x0 + 0.1f, 0.5f * (b::kFenceRailYMin + b::kFenceRailYMax)));
    }
    // A floor point is shadowed through a slat and lit through a gap, under a light tilted 45 deg toward +z.
    const glm::vec3 light = glm::normalize(glm::vec3(0.0f, -1.0f, -1.0f));  // travels toward -z
    EXPECT_TRUE(b::fenceShadowsPoint({-3.5f, 0.0f, -1.0f}, light));   // ray meets the fence at (-3.5, 1)
    EXPECT_FALSE(b::fenceShadowsPoint({-3.0f, 0.0f, -1.0f}, light));  // (-3.0, 1): a gap
    EXPECT_TRUE(b::fenceShadowsPoint({-3.0f, 0.0f, -2.0f}, light));   // (-3.0, 2): the rail
    EXPECT_FALSE(b::fenceShadowsPoint({-3.5f, 0.0f, 1.0f}, light));   // in front of the fence
}

TEST(BuiltinScenes, SpherePlaneIsFinelyTessellated) {
    const Scene s = builtinOrDie("sphere-plane");
    const Mesh* sphere = meshNamed(s, "sphere");
    ASSERT_NE(sphere, nullptr);
    EXPECT_EQ(sphere->triangleCount(), std::size_t(b::kSpherePlaneSegments * (2 * b::kSpherePlaneRings - 2)));
    for (std::size_t i = 0; i < sphere->positions.size(); ++i) {
        const glm::vec3 d = sphere->positions[i] - b::kSpherePlaneCenter;
        EXPECT_NEAR(glm::length(d), b::kSpherePlaneRadius, 1e-5f);
        EXPECT_GT(glm::dot(sphere->normals[i], d), 0.999f);
    }
    expectVecNear(s.bounds.min, {-10, 0, -10}, 1e-5f);
    EXPECT_NEAR(s.bounds.max.y, 3.0f, 1e-5f);
}
