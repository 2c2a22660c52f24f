// Issue 20 (a view's casters in a few multi-draw calls) and issue 22 (a transform buffer update, not a re-upload):
//  - the batched shadow pass equals, texel for texel, the map of an independently built copy of the scene whose
//    instances are baked on the CPU into one mesh per material with an identity transform (mirrored instances'
//    triangles reversed, as their flipped front face makes them): builtin:city's cascades (bit for bit), and
//    AlphaBlendModeTest's alpha-tested casters with mirrored, rotated and scaled copies added (the same texels
//    covered, depths within the float rounding of a transform);
//  - a pass issues one multi-draw call per group of casters sharing their state, not one per caster;
//  - an animation step that moves one instance uploads no geometry, only that instance's transform, and the shadow
//    map equals a fresh GpuScene's.
#include "gl_fixture.h"

#include "frame/face_culling.h"
#include "light/scene_lights.h"
#include "scene/scene_animation.h"
#include "scene/scene_source.h"
#include "shadow/shadow_pass.h"

#include <glm/ext/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

namespace shadowlab::test {
namespace {

class BatchedShadowPass : public GlTest {};

// The oracle: every instance's triangles transformed on the CPU in double precision, relative to `origin`, into
// one mesh per material with an identity transform. A mirrored instance's triangles are reversed so that their front
// faces stay counter-clockwise in world space. Drawn from a GpuScene at origin 0, each vertex reaches the shader as
// computed here (an identity model matrix changes no bit).
Scene bakedCopy(const Scene& scene, const glm::dvec3& origin) {
    Scene baked;
    baked.name = scene.name + " (baked)";
    baked.materials = scene.materials;
    baked.images = scene.images;
    std::map<int, std::size_t> meshOfMaterial;
    for (const Instance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes[std::size_t(instance.mesh)];
        auto [it, added] = meshOfMaterial.try_emplace(mesh.material, baked.meshes.size());
        if (added) {
            baked.meshes.emplace_back();
            baked.meshes.back().material = mesh.material;
            baked.meshes.back().name = "baked material " + std::to_string(mesh.material);
        }
        Mesh& out = baked.meshes[it->second];
        glm::dmat4 model(instance.transform);
        model[3] -= glm::dvec4(origin, 0.0);
        const bool mirrored = glm::determinant(glm::dmat3(instance.transform)) < 0.0;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const std::uint32_t corners[3] = {mesh.indices[t], mesh.indices[t + (mirrored ? 2 : 1)],
                                              mesh.indices[t + (mirrored ? 1 : 2)]};
            for (std::uint32_t v : corners) {
                out.indices.push_back(std::uint32_t(out.positions.size()));
                out.positions.push_back(glm::vec3(model * glm::dvec4(glm::dvec3(mesh.positions[v]), 1.0)));
                out.normals.push_back(glm::vec3(0.0f, 1.0f, 0.0f));  // the depth passes read no normal
                out.uvs.push_back(v < mesh.uvs.size() ? mesh.uvs[v] : glm::vec2(0.0f));
            }
        }
    }
    for (std::size_t m = 0; m < baked.meshes.size(); ++m) baked.instances.push_back({int(m), glm::mat4(1.0f), -1});
    baked.computeBounds();
    return baked;
}

struct MapDifference {
    std::size_t written = 0;     // texels a caster wrote (not the clear value) in the oracle's map
    std::size_t coverage = 0;    // texels written in one map and not the other
    std::size_t differ = 0;      // texels both wrote, at different depths
    std::size_t overTolerance = 0;
    double maxDifference = 0.0;
};

MapDifference compare(const std::vector<float>& batched, const std::vector<float>& oracle, float clear,
                      double tolerance) {
    MapDifference d;
    EXPECT_EQ(batched.size(), oracle.size());
    for (std::size_t i = 0; i < std::min(batched.size(), oracle.size()); ++i) {
        d.written += oracle[i] != clear;
        if (batched[i] == oracle[i]) continue;
        if ((batched[i] == clear) != (oracle[i] == clear)) {
            ++d.coverage;
            continue;
        }
        ++d.differ;
        const double difference = std::abs(double(batched[i]) - double(oracle[i]));
        d.maxDifference = std::max(d.maxDifference, difference);
        d.overTolerance += difference > tolerance;
    }
    return d;
}

// The groups the pass's rule makes of a view's casters: one per face-cull state, and per material for the
// alpha-tested ones (the state face_culling.h gives each draw).
std::size_t expectedGroups(const GpuScene& gpu, const CasterSelection& casters, CullMode mode) {
    std::set<std::tuple<int, int>> groups;
    for (std::uint32_t d : casters.draws) {
        const GpuDraw& draw = gpu.draws()[d];
        const Material* material = draw.material >= 0 ? &gpu.scene().materials[std::size_t(draw.material)] : nullptr;
        const bool masked = material && material->alphaMode == AlphaMode::Mask;
        groups.emplace(masked ? draw.material : -1, shadowFaceCullState(mode, material, draw.mirrored).key());
    }
    return groups.size();
}

// Renders each view of `views` from `scene` (batched) and from its baked copy into a map of `resolution`, and
// checks that they cover the same texels, at depths within `depthTolerance` of each other (0: bit for bit), and that
// the pass issued one multi-draw call per group.
void expectBatchedEqualsBaked(const Scene& scene, const std::vector<LightSpace>& views, const glm::dvec3& origin,
                              const ShadowMapSettings& shadow, bool depthClamp, int resolution,
                              const std::string& label, double depthTolerance) {
    const Scene baked = bakedCopy(scene, origin);
    GpuScene batchedScene(scene, origin);
    GpuScene bakedScene(baked, glm::dvec3(0.0));
    ShadowPass pass;
    ShadowMap batchedMap, bakedMap;
    ASSERT_EQ(batchedMap.ensure(resolution, DepthFormat::D32F, 16384), "");
    ASSERT_EQ(bakedMap.ensure(resolution, DepthFormat::D32F, 16384), "");
    for (std::size_t v = 0; v < views.size(); ++v) {
        const LightSpace& space = views[v];
        const ShadowPassCounts counts = pass.run(batchedScene, space, shadow, depthClamp, batchedMap);
        pass.run(bakedScene, space, shadow, depthClamp, bakedMap);
        const std::string where = label + " view " + std::to_string(v);
        ASSERT_GT(counts.castersDrawn, 0) << where;
        const CasterSelection selection = castersInVolume(batchedScene, space);
        EXPECT_EQ(std::size_t(counts.drawCalls), expectedGroups(batchedScene, selection, shadow.cullMode))
            << where << ": one multi-draw call per group, " << counts.castersDrawn << " casters";
        const MapDifference d =
            compare(batchedMap.readDepth(), bakedMap.readDepth(), space.reversedZ ? 0.0f : 1.0f, depthTolerance);
        std::printf("%s: %d casters in %d draw calls; %zu texels written, %zu covered differently, %zu at another "
                    "depth (max %.3g)\n",
                    where.c_str(), counts.castersDrawn, counts.drawCalls, d.written, d.coverage, d.differ,
                    d.maxDifference);
        EXPECT_GT(d.written, std::size_t(resolution)) << where << ": the view holds casters";
        EXPECT_EQ(d.coverage, 0u) << where << ": texels one map covers and the other does not";
        EXPECT_EQ(d.overTolerance, 0u) << where << ": texels deeper or shallower than the baked copy's by more than "
                                       << depthTolerance << " (max " << d.maxDifference << ")";
    }
}

TEST_F(BatchedShadowPass, CityCascadesEqualTheMapOfABakedSingleMeshCopy) {
    const Scene scene = loadBuiltin("city");
    Settings s = loadShippedPreset("default");
    s.useSceneLights = true;
    Renderer renderer;
    // The city's sun (useSceneLights) in 4 cascades, as bench --planner measures them (docs/performance.md).
    Settings planned = withEffectiveLights(s, scene);
    planned.useSceneLights = false;
    planned.lights[0].projection.fit = ProjectionFit::Cascades;
    planned.lights[0].projection.cascadeCount = 4;
    planned.lights[0].shadow.resolution = 512;
    const View view = renderView(renderer, scene, planned, 160, 90);
    ASSERT_TRUE(view.stats.ok) << view.stats.error;
    std::vector<LightSpace> cascades;
    for (const ShadowView& v : frameViewsOf(view.stats, 0)) cascades.push_back(v.space);
    ASSERT_EQ(cascades.size(), 4u);
    expectBatchedEqualsBaked(scene, cascades, view.stats.renderOrigin, planned.lights[0].shadow,
                             planned.lights[0].depthClampApplies(), 512, "city cascade", 0.0);
}

// The city's instances have identity transforms: its maps agree bit for bit. Here the GPU's float model * position
// and the oracle's double-precision one rounded once differ in the last bits: the same texels are covered, at depths
// within this (about 2e-6 on llvmpipe; a misplaced or misoriented caster moves them by orders of magnitude more).
constexpr double kTransformRounding = 1e-5;

TEST_F(BatchedShadowPass, AlphaTestedMirroredAndRotatedInstancesEqualTheMapOfABakedCopy) {
    const std::string path = std::string(SHADOWLAB_SHARED_SCENES) + "/AlphaBlendModeTest/AlphaBlendModeTest.gltf";
    if (!std::filesystem::exists(path))
        GTEST_SKIP() << "the shared scenes folder " << SHADOWLAB_SHARED_SCENES << " is absent (needs " << path << ")";
    SceneLoadResult loaded = loadScene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    Scene scene = *loaded.scene;
    ASSERT_TRUE(scene.hasAlphaMaskedCasters());
    // Beside each of the file's instances: a mirrored copy (negative x scale), a rotated one and one mirrored in y
    // with a non-uniform scale, tilted.
    const std::size_t fileInstances = scene.instances.size();
    for (std::size_t i = 0; i < fileInstances; ++i) {
        const Instance original = scene.instances[i];
        const glm::mat4 t(original.transform), one(1.0f);
        const glm::mat4 copies[3] = {
            glm::translate(one, {0.2f, 0.0f, -2.5f}) * glm::scale(one, {-1.0f, 1.0f, 1.0f}) * t,
            glm::translate(one, {0.0f, 0.3f, 2.5f}) * glm::rotate(one, 0.5f, {0.0f, 1.0f, 0.0f}) * t,
            glm::translate(one, {0.0f, 2.0f, -5.0f}) * glm::rotate(one, 0.3f, {1.0f, 0.0f, 0.0f}) *
                glm::scale(one, {1.0f, -0.7f, 1.3f}) * t};
        for (const glm::mat4& c : copies) scene.instances.push_back({original.mesh, c, -1});
    }
    scene.computeBounds();
    int mirrored = 0;
    for (const Instance& instance : scene.instances) mirrored += instance.mirrored();
    ASSERT_GE(mirrored, int(2 * fileInstances));
    ASSERT_EQ(scene.invariantError(), "");

    Settings s = loadShippedPreset("default");
    s.lights[0].direction = glm::vec3(-0.35f, -1.0f, -0.25f);
    Renderer renderer;
    const View view = renderView(renderer, scene, s, 160, 90);
    ASSERT_TRUE(view.stats.ok) << view.stats.error;
    // Back and front culling (single-sided casters, mirrored ones flipped) and none; no bias: the geometry alone.
    for (CullMode cull : {CullMode::Back, CullMode::Front, CullMode::None}) {
        ShadowMapSettings shadow = s.lights[0].shadow;
        shadow.cullMode = cull;
        shadow.depthBias = shadow.slopeScaledDepthBias = shadow.depthBiasClamp = 0.0f;
        expectBatchedEqualsBaked(scene, {view.stats.light}, view.stats.renderOrigin, shadow,
                                 s.lights[0].depthClampApplies(), 512,
                                 "AlphaBlendModeTest cull " + std::to_string(int(cull)), kTransformRounding);
    }
}

// The city's farthest cascade holds thousands of one-box casters: they go out in one multi-draw call (one cull state).
TEST_F(BatchedShadowPass, APassIssuesOneDrawCallPerStateGroupNotPerCaster) {
    const Scene scene = loadBuiltin("city");
    Settings s = loadShippedPreset("default");
    s.useSceneLights = true;
    Settings planned = withEffectiveLights(s, scene);
    planned.useSceneLights = false;
    planned.lights[0].projection.fit = ProjectionFit::Cascades;
    planned.lights[0].projection.cascadeCount = 4;
    planned.lights[0].shadow.resolution = 256;
    Renderer renderer;
    const View view = renderView(renderer, scene, planned, 160, 90);
    ASSERT_TRUE(view.stats.ok) << view.stats.error;
    int views = 0;
    for (const ShadowViewStats& v : view.stats.views) {
        if (!v.ran) continue;
        ++views;
        EXPECT_GT(v.castersDrawn, 100) << v.name;
        EXPECT_EQ(v.drawCalls, 1) << v.name << ": " << v.castersDrawn
                                  << " casters, every one single-sided and unmirrored";
    }
    EXPECT_EQ(views, 4);
    EXPECT_EQ(view.stats.shadowDrawCalls, 4);
}

// Issue 22: the animation step moves one instance (animated_boxes' "Spin" turns one box): no geometry goes up, only
// its transform, for a scene posed in place and for a posed copy (the editor's timeline); the shadow map equals the
// one a fresh renderer (a fresh GpuScene) draws of the same pose.
TEST_F(BatchedShadowPass, AnAnimationStepUpdatesTransformsOnlyAndTheMapEqualsAFreshUpload) {
    SceneLoadResult loaded = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/animated_boxes.gltf");
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    Scene scene = *loaded.scene;
    Settings s = loadShippedPreset("default");
    s.lights[0].direction = glm::vec3(-0.3f, -1.0f, -0.4f);
    s.animation.play = "Spin";
    s.animation.time = 0.0f;
    ASSERT_EQ(poseScene(scene, s.animation), "");
    Renderer renderer;
    const View first = renderView(renderer, scene, s, 160, 90);
    ASSERT_TRUE(first.stats.ok) << first.stats.error;
    EXPECT_TRUE(first.stats.sceneUpload.ran);
    EXPECT_GT(first.stats.geometryBytesUploaded, 0u) << first.stats.sceneUpload.reason;
    EXPECT_EQ(renderView(renderer, scene, s, 160, 90).stats.sceneUpload.ran, false) << "nothing changed";

    const std::vector<float> rest(renderer.shadowMap().readDepth());
    for (const bool copy : {false, true}) {
        s.animation.time += 0.4f;
        Scene posedCopy;
        if (copy) posedCopy = scene;  // new vertex arrays with the same contents
        Scene& posed = copy ? posedCopy : scene;
        ASSERT_EQ(poseScene(posed, s.animation), "");
        const View stepped = renderView(renderer, posed, s, 160, 90);
        ASSERT_TRUE(stepped.stats.ok) << stepped.stats.error;
        const std::string where = copy ? "a posed copy" : "posed in place";
        EXPECT_TRUE(stepped.stats.sceneUpload.ran) << where;
        EXPECT_EQ(stepped.stats.geometryBytesUploaded, 0u) << where << ": " << stepped.stats.sceneUpload.reason;
        EXPECT_EQ(stepped.stats.transformBytesUploaded, sizeof(glm::mat4))
            << where << ": one instance moved: " << stepped.stats.sceneUpload.reason;
        EXPECT_EQ(stepped.stats.sceneUpload.reason.rfind("transforms updated, 64 bytes", 0), 0u)
            << stepped.stats.sceneUpload.reason;
        EXPECT_TRUE(stepped.stats.shadowPass.ran) << where << ": the moved caster's view re-renders";
        const std::vector<float> updated(renderer.shadowMap().readDepth());
        EXPECT_NE(updated, rest) << where << ": the box turned";

        Renderer fresh;
        const View uploaded = renderView(fresh, posed, s, 160, 90);
        ASSERT_TRUE(uploaded.stats.ok) << uploaded.stats.error;
        EXPECT_GT(uploaded.stats.geometryBytesUploaded, 0u);
        EXPECT_EQ(fresh.shadowMap().readDepth(), updated) << where << ": the map equals a fresh upload's";
        EXPECT_EQ(uploaded.rgba, stepped.rgba) << where << ": and so does the picture";
    }
}

}  // namespace
}  // namespace shadowlab::test
