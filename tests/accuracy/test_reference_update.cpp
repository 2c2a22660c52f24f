// The reference follows motion cheaply (issue 22): one BVH per mesh under a top level of instances. After an
// animation step, updateTransforms() moves the instances and re-commits the top level only; what it answers equals,
// pixel for pixel, a reference built from scratch at that pose (builtin:city-traffic, and a glTF with alpha-MASK
// casters), without building any mesh BVH again. The accuracy meter takes that path when only transforms changed.
#include "gl_fixture.h"
#include "reference_fixture.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_animation.h"
#include "scene/scene_source.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>

namespace shadowlab::test {
namespace {

// A grid of sample points `step` apart on a plane, relative to `origin`: the "pixels" traceVisibility classifies.
// Columns run along `u` from `corner`, rows along `v`; every normal is `normal`.
SurfaceSamples grid(const glm::dvec3& origin, const glm::dvec3& corner, const glm::dvec3& u, int columns,
                    const glm::dvec3& v, int rows, const glm::dvec3& normal) {
    SurfaceSamples s;
    s.width = columns;
    s.height = rows;
    const std::size_t n = std::size_t(s.width) * std::size_t(s.height);
    s.draw.assign(n, 0);
    s.instance.assign(n, 0);
    s.triangle.assign(n, 0);
    s.normal.assign(n, normal);
    s.finite.assign(n, 1);
    s.point.resize(n);
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x)
            s.point[std::size_t(y) * std::size_t(s.width) + std::size_t(x)] =
                corner + (x + 0.5) * u + (y + 0.5) * v - origin;
    return s;
}

// The ground y = 0 over [x0, x1] x [z0, z1], a sample every `step`, seen from above.
SurfaceSamples ground(const glm::dvec3& origin, double x0, double x1, double z0, double z1, double step) {
    return grid(origin, {x0, 0.0, z0}, {step, 0.0, 0.0}, int((x1 - x0) / step), {0.0, 0.0, step},
                int((z1 - z0) / step), {0.0, 1.0, 0.0});
}

std::size_t differing(const VisibilityResult& a, const VisibilityResult& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.classes.size(); ++i) n += a.classes[i] != b.classes[i];
    return n;
}

std::size_t shadowed(const VisibilityResult& v) {
    std::size_t n = 0;
    for (PixelClass c : v.classes) n += c == PixelClass::Shadowed;
    return n;
}

Scene cityTraffic() {
    std::optional<Scene> scene = makeBuiltinScene("city-traffic");
    if (!scene) throw std::runtime_error("no builtin:city-traffic");
    return std::move(*scene);
}

// The instance a city-traffic car's node places.
std::size_t carInstance(const Scene& scene, int car) {
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
        if (scene.instances[i].node >= 0 && scene.nodes[std::size_t(scene.instances[i].node)].gltfIndex == car) return i;
    throw std::runtime_error("no car " + std::to_string(car));
}

TEST(ReferenceUpdate, OneCarMovedThroughTheUpdatePathEqualsAFreshBuildWithoutBuildingAMeshBvh) {
    Scene scene = cityTraffic();
    const glm::dvec3 origin = scene.bounds.centreOrOrigin();
    ReferenceLight sun;
    sun.direction = glm::normalize(glm::dvec3(builtin::kCitySunDir));
    const double radius = double(scene.bounds.radius());
    // The road where car 5 crosses the street x = 0 in the sun, 36 m ahead of the eye, a sample every quarter metre.
    const SurfaceSamples road = ground(origin, -20.0, 20.0, 390.0, 420.0, 0.25);

    EmbreeScene bvh(scene, origin);
    const std::size_t meshBuilds = bvh.meshBuilds(), topCommits = bvh.topCommits();
    EXPECT_EQ(meshBuilds, bvh.meshBvhs());
    EXPECT_EQ(topCommits, 1u);
    const VisibilityResult before = traceVisibility(bvh, road, sun, radius, nullptr);

    // One animation step of car 5 alone: its instance moves to its pose half a second later.
    Scene later = scene;
    poseScene(later, {0}, 0.5);
    const std::size_t car = carInstance(scene, 5);
    scene.instances[car].transform = later.instances[car].transform;
    ASSERT_TRUE(bvh.sameGeometry(scene));
    EXPECT_EQ(bvh.updateTransforms(scene, origin), 1u);
    EXPECT_EQ(bvh.meshBuilds(), meshBuilds) << "the update rebuilt a mesh BVH";
    EXPECT_EQ(bvh.topCommits(), topCommits + 1);
    const VisibilityResult updated = traceVisibility(bvh, road, sun, radius, nullptr);

    const EmbreeScene fresh(scene, origin);
    const VisibilityResult rebuilt = traceVisibility(fresh, road, sun, radius, nullptr);
    EXPECT_EQ(differing(updated, rebuilt), 0u) << "of " << road.size() << " samples";
    // The step matters: the car's shadow moved over hundreds of samples (a stale BVH would be wrong there).
    EXPECT_GT(differing(before, rebuilt), 200u);
    EXPECT_GT(shadowed(rebuilt), 1000u);
    std::printf("car 5 moved 0.5 s: %zu of %zu road samples changed V; update %.3f ms, rebuild %.1f ms (%zu mesh BVHs)\n",
                differing(before, rebuilt), road.size(), bvh.updateMilliseconds(), fresh.buildMilliseconds(),
                fresh.meshBvhs());

    // Nothing moved: nothing is committed.
    EXPECT_EQ(bvh.updateTransforms(scene, origin), 0u);
    EXPECT_EQ(bvh.topCommits(), topCommits + 1);
}

TEST(ReferenceUpdate, TheGeometryTestTellsATransformChangeFromAGeometryChange) {
    Scene scene = cityTraffic();
    const glm::dvec3 origin = scene.bounds.centreOrOrigin();
    const EmbreeScene bvh(scene, origin);
    poseScene(scene, {0}, 10.0);
    EXPECT_TRUE(bvh.sameGeometry(scene)) << "an animation step changes transforms only";
    std::vector<char> casting(scene.instances.size(), 1);
    casting[carInstance(scene, 2)] = 0;
    EXPECT_FALSE(bvh.sameGeometry(scene, casting)) << "a caster excluded";
    const Scene copy = scene;
    EXPECT_FALSE(bvh.sameGeometry(copy)) << "another scene object";
    Scene edited = cityTraffic();
    const EmbreeScene other(edited, origin);
    edited.materials[std::size_t(edited.meshes[0].material)].doubleSided = true;
    EXPECT_FALSE(other.sameGeometry(edited)) << "a material's culling changed";
    edited = cityTraffic();
    const EmbreeScene third(edited, origin);
    edited.instances.pop_back();
    EXPECT_FALSE(third.sameGeometry(edited)) << "an instance removed";
}

// "Only transforms changed" is scene_fingerprint.h's layout key, the GPU upload's too: a mesh whose triangles are
// replaced by as many others (its winding flipped: the shadow pass culls the other faces) or a picture replaced is a
// geometry change, though the Scene object, every count and the vertex buffer are the same.
TEST(ReferenceUpdate, TrianglesOrPicturesReplacedInPlaceAreAGeometryChange) {
    Scene scene = cityTraffic();
    const glm::dvec3 origin = scene.bounds.centreOrOrigin();
    const EmbreeScene bvh(scene, origin);
    ASSERT_TRUE(bvh.sameGeometry(scene));
    Mesh& mesh = scene.meshes[std::size_t(scene.instances[carInstance(scene, 0)].mesh)];
    std::vector<std::uint32_t> flipped = mesh.indices;
    for (std::size_t t = 0; t + 2 < flipped.size(); t += 3) std::swap(flipped[t + 1], flipped[t + 2]);
    mesh.indices = std::move(flipped);
    EXPECT_FALSE(bvh.sameGeometry(scene)) << "the car's triangles were replaced (same count, other winding)";

    Scene pictured = cityTraffic();
    pictured.images.push_back(Image{1, 1, std::vector<std::uint8_t>(4, 0)});
    const EmbreeScene withImage(pictured, origin);
    ASSERT_TRUE(withImage.sameGeometry(pictured));
    pictured.images[0].rgba = std::vector<std::uint8_t>(4, 255);
    EXPECT_FALSE(withImage.sameGeometry(pictured)) << "the picture an alpha mask would read was replaced";
}

// AlphaBlendModeTest's MASK casters moved by hand (an animation step of each): occlusion and the first hit, with its
// MASK flag resolved through the instance id, equal a fresh build's at every sample.
TEST(ReferenceUpdate, MovedAlphaMaskCastersEqualAFreshBuild) {
    const std::string path = std::string(SHADOWLAB_SHARED_SCENES) + "/AlphaBlendModeTest/AlphaBlendModeTest.gltf";
    if (!std::filesystem::exists(path))
        GTEST_SKIP() << "the shared scenes folder " << SHADOWLAB_SHARED_SCENES << " is absent (needs " << path << ")";
    SceneLoadResult loaded = loadScene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    Scene& scene = *loaded.scene;
    const glm::dvec3 origin = scene.bounds.centreOrOrigin();
    // The test quads stand in the plane z = 0 in front of the bed's back panel (z < -0.47): samples on the plane
    // z = -0.3 between them, lit by a light travelling -z, look through the quads' alpha.
    ReferenceLight down;
    down.direction = glm::dvec3(0.0, 0.0, -1.0);
    const double radius = double(scene.bounds.radius());
    const SurfaceSamples below =
        grid(origin, {-4.3, 0.15, -0.3}, {0.01, 0.0, 0.0}, 860, {0.0, 0.01, 0.0}, 180, {0.0, 0.0, 1.0});

    EmbreeScene bvh(scene, origin);
    ASSERT_TRUE(bvh.hasAlphaMask());
    const std::size_t meshBuilds = bvh.meshBuilds();
    const VisibilityResult before = traceVisibility(bvh, below, down, radius, nullptr);
    std::size_t masked = 0;
    for (Instance& instance : scene.instances) {
        const Material* material = scene.materialOf(scene.meshes[std::size_t(instance.mesh)]);
        if (!material || material->alphaMode != AlphaMode::Mask) continue;
        instance.transform = glm::translate(glm::mat4(1.0f), glm::vec3(0.13f, 0.0f, 0.07f)) * instance.transform;
        ++masked;
    }
    ASSERT_GT(masked, 0u);
    ASSERT_TRUE(bvh.sameGeometry(scene));
    EXPECT_EQ(bvh.updateTransforms(scene, origin), masked);
    EXPECT_EQ(bvh.meshBuilds(), meshBuilds);
    const EmbreeScene fresh(scene, origin);
    const VisibilityResult updated = traceVisibility(bvh, below, down, radius, nullptr);
    const VisibilityResult rebuilt = traceVisibility(fresh, below, down, radius, nullptr);
    EXPECT_EQ(differing(updated, rebuilt), 0u) << "of " << below.size() << " samples";
    EXPECT_GT(differing(before, rebuilt), 100u) << "the MASK casters' shadows moved";

    // The first hit with and without the alpha test: the same face, and MASK faces named through the instance.
    std::size_t maskHits = 0, seenThrough = 0, mismatches = 0;
    for (bool ignoreAlpha : {false, true}) {
        HitRules rules;
        rules.ignoreAlpha = ignoreAlpha;
        for (std::size_t i = 0; i < below.size(); ++i) {
            const glm::vec3 p(below.point[i]);
            const RayHit u = bvh.firstHit(p, {0.0f, 0.0f, 1.0f}, 1e30f, rules);
            const RayHit f = fresh.firstHit(p, {0.0f, 0.0f, 1.0f}, 1e30f, rules);
            mismatches += u.hit != f.hit || u.t != f.t || u.geometry != f.geometry || u.alphaMask != f.alphaMask;
            if (!u.hit) continue;
            const EmbreeScene::GeometryInfo& g = bvh.geometry(u.geometry);
            const Material* material = scene.materialOf(scene.meshes[g.mesh]);
            EXPECT_EQ(u.alphaMask, material && material->alphaMode == AlphaMode::Mask);
            EXPECT_EQ(scene.instances[g.instance].mesh, int(g.mesh));
            if (ignoreAlpha && u.alphaMask) {
                ++maskHits;
                seenThrough += !bvh.occluded(p, {0.0f, 0.0f, 1.0f}, 1e30f);
            }
        }
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_GT(maskHits, 100u);
    EXPECT_GT(seenThrough, 10u) << "transparent texels of moved MASK casters let light through";
}

// The same world geometry twice: builtin:textbook's meshes with their vertices stored 1e6 from their own origin
// (as a file with baked large coordinates has them) and placed back by the instance, and the same float vertices
// stored near the origin. Each mesh BVH is centred on its mesh, so both answer alike at every 1 cm sample (a BVH in
// the mesh's own coordinates would round the far one's rays to 1/16 unit).
TEST(ReferenceUpdate, AMeshFarFromItsOwnOriginKeepsFloatPrecision) {
    const glm::vec3 offset(1.0e6f, 0.0f, 1.0e6f);
    Scene far = *makeBuiltinScene("textbook");
    Scene near = far;
    for (std::size_t m = 0; m < far.meshes.size(); ++m)
        for (std::size_t i = 0; i < far.meshes[m].positions.size(); ++i) {
            glm::vec3& p = far.meshes[m].positions[i];
            p += offset;                                // rounded to float's 1/16 at 1e6
            near.meshes[m].positions[i] = p - offset;  // exact: the same vertices near the origin
        }
    for (Instance& instance : far.instances) instance.transform = glm::translate(glm::mat4(1.0f), -offset);
    near.computeBounds();
    far.computeBounds();
    const glm::dvec3 origin = near.bounds.centreOrOrigin();
    ReferenceLight light;
    light.direction = glm::normalize(glm::dvec3(-0.4, -1.0, -0.3));
    const SurfaceSamples floor = ground(origin, -6.0, 6.0, -6.0, 6.0, 0.01);
    const VisibilityResult a = traceVisibility(EmbreeScene(near, origin), floor, light, 10.0, nullptr);
    const VisibilityResult b = traceVisibility(EmbreeScene(far, origin), floor, light, 10.0, nullptr);
    EXPECT_GT(shadowed(a), 10000u);
    EXPECT_EQ(differing(a, b), 0u) << "of " << floor.size() << " samples 1 cm apart";
}

class ReferenceUpdateMeter : public GlTest {};

// measure(), an animation step later on the same (posed in place) scene: the meter updates its BVH, and the result
// equals a fresh meter's at that time pixel for pixel.
TEST_F(ReferenceUpdateMeter, AnAnimationStepUpdatesTheMetersBvhAndMeasuresAsAFreshMeter) {
    Scene scene = cityTraffic();
    Settings settings = loadShippedPreset("default");
    settings.useSceneLights = true;
    const int width = 320, height = 180;
    const Camera camera = cameraFor(settings.camera, scene, double(width) / height);
    AccuracyMeter meter;
    const AccuracyReport first = meter.measure(scene, settings, camera, width, height);
    ASSERT_TRUE(first.ok) << first.error;
    EXPECT_FALSE(first.cost.bvhUpdated);

    settings.animation.time = 0.5f;
    ASSERT_EQ(poseScene(scene, settings.animation), "");
    const AccuracyReport stepped = meter.measure(scene, settings, camera, width, height);
    ASSERT_TRUE(stepped.ok) << stepped.error;
    EXPECT_TRUE(stepped.cost.bvhUpdated);
    EXPECT_FALSE(stepped.cost.bvhReused);
    EXPECT_EQ(stepped.cost.instancesMoved, std::size_t(builtin::kCityCars));
    EXPECT_EQ(stepped.cost.bvhBuildMs, 0.0);

    AccuracyMeter freshMeter;
    const AccuracyReport fresh = freshMeter.measure(scene, settings, camera, width, height);
    ASSERT_TRUE(fresh.ok) << fresh.error;
    EXPECT_FALSE(fresh.cost.bvhUpdated);
    std::size_t classes = 0, changed = 0;
    for (std::size_t i = 0; i < fresh.pixelClass.size(); ++i) {
        classes += stepped.pixelClass[i] != fresh.pixelClass[i];
        changed += first.pixelClass[i] != fresh.pixelClass[i];
    }
    EXPECT_EQ(classes, 0u);
    EXPECT_GT(changed, 5u) << "the cars in view moved their shadows";
    EXPECT_EQ(stepped.counts.wrong, fresh.counts.wrong);

    // Another scene object (the geometry may differ): a full build again.
    const Scene copy = scene;
    const AccuracyReport other = meter.measure(copy, settings, camera, width, height);
    ASSERT_TRUE(other.ok) << other.error;
    EXPECT_FALSE(other.cost.bvhUpdated);
    EXPECT_GT(other.cost.bvhBuildMs, 0.0);
}

}  // namespace
}  // namespace shadowlab::test
