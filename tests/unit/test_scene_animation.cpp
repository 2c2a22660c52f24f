// glTF animation (tests/data/scenes/animated_boxes.gltf, written by make_animated_boxes.py): each channel path and
// interpolation plays to the pose its sampler defines, at keys and between them; times outside the keys clamp; the
// bounds hold every pose; hostile animations are skipped with a message naming the animation and channel while the
// rest of the file loads; skins and morph weights are said not to be played.
#include "scene/gltf_loader.h"
#include "scene/scene_animation.h"
#include "settings/preset_io.h"
#include "settings/settings_fields.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace shadowlab;

namespace {

const std::string kScenes = std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/";
const std::string kRegressions = std::string(SHADOWLAB_SOURCE_DIR) + "/tests/fuzz/regressions/gltf/";

Scene load(const std::string& path) {
    SceneLoadResult r = loadGltfScene(path);
    EXPECT_TRUE(r.scene) << r.error;
    return r.scene ? std::move(*r.scene) : Scene{};
}

Scene boxes() { return load(kScenes + "animated_boxes.gltf"); }

int nodeNamed(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].name == name) return int(i);
    return -1;
}

// The world transform of the (first) instance node `name` placed.
glm::dmat4 placed(const Scene& scene, const std::string& name) {
    const int node = nodeNamed(scene, name);
    for (const Instance& i : scene.instances)
        if (i.node == node) return glm::dmat4(i.transform);
    ADD_FAILURE() << "no instance of node " << name;
    return glm::dmat4(1.0);
}

Scene posed(const std::string& play, double time) {
    Scene scene = boxes();
    AnimationSettings a;
    a.play = play;
    a.time = float(time);
    EXPECT_EQ(poseScene(scene, a), "");
    return scene;
}

glm::dvec3 origin(const glm::dmat4& m) { return glm::dvec3(m[3]); }

void expectNear(const glm::dvec3& a, const glm::dvec3& b, const char* what) {
    EXPECT_LT(glm::length(a - b), 1e-5) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") expected (" << b.x
                                        << ", " << b.y << ", " << b.z << ")";
}

// The matrix T * R(angle about axis) * S.
glm::dmat4 trs(glm::dvec3 t, double degrees, glm::dvec3 axis, glm::dvec3 s) {
    return glm::scale(glm::rotate(glm::translate(glm::dmat4(1.0), t), glm::radians(degrees), axis), s);
}

void expectMatrix(const glm::dmat4& a, const glm::dmat4& b, const char* what) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], 1e-5) << what << " [" << c << "][" << r << "]";
}

bool hasWarning(const Scene& scene, const std::string& part) {
    return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

}  // namespace

TEST(SceneAnimation, TheFileLoadsItsThreeAnimations) {
    const Scene scene = boxes();
    EXPECT_EQ(scene.invariantError(), "");
    ASSERT_EQ(scene.animations.size(), 3u);
    EXPECT_EQ(scene.animations[0].name, "Move");
    EXPECT_EQ(scene.animations[1].name, "Spin");
    EXPECT_EQ(scene.animations[2].name, "Cubic");
    EXPECT_EQ(scene.animations[0].channels.size(), 2u);
    EXPECT_DOUBLE_EQ(scene.animations[0].end, 2.0);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    // Loaded, the instances stand where the file puts its nodes (the rest pose).
    expectNear(origin(placed(scene, "Mover")), {0, 1, -4}, "rest Mover");
}

TEST(SceneAnimation, LinearTranslationAtKeysBetweenAndClampedOutside) {
    expectNear(origin(placed(posed("Move", 0.0), "Mover")), {-4, 1, 0}, "key 0");
    expectNear(origin(placed(posed("Move", 0.5), "Mover")), {0, 1, 0}, "halfway to key 1");
    expectNear(origin(placed(posed("Move", 1.0), "Mover")), {4, 1, 0}, "key 1");
    expectNear(origin(placed(posed("Move", 1.5), "Mover")), {4, 1, 2}, "halfway to key 2");
    expectNear(origin(placed(posed("Move", 7.0), "Mover")), {4, 1, 4}, "after the last key: it holds");
    // The child moves with its parent: the hierarchy is re-evaluated.
    expectNear(origin(placed(posed("Move", 1.5), "Rider")), {4, 3, 2}, "Rider under Mover");
    // "none": the file's pose.
    expectNear(origin(placed(posed("none", 1.5), "Mover")), {0, 1, -4}, "none");
}

TEST(SceneAnimation, StepScaleHoldsUntilTheNextKey) {
    const glm::dvec3 t(-6, 0.5, -6);
    expectMatrix(placed(posed("Move", 0.0), "Grower"), trs(t, 0, {0, 1, 0}, {1, 1, 1}), "key 0");
    expectMatrix(placed(posed("Move", 0.999), "Grower"), trs(t, 0, {0, 1, 0}, {1, 1, 1}), "just before key 1");
    expectMatrix(placed(posed("Move", 1.0), "Grower"), trs(t, 0, {0, 1, 0}, {0.5, 3, 0.5}), "key 1");
    expectMatrix(placed(posed("Move", 1.7), "Grower"), trs(t, 0, {0, 1, 0}, {0.5, 3, 0.5}), "between 1 and 2");
    expectMatrix(placed(posed("Move", 2.0), "Grower"), trs(t, 0, {0, 1, 0}, {1, 1, 1}), "key 2");
}

TEST(SceneAnimation, LinearRotationSlerpsTheShortWay) {
    const glm::dvec3 t(6, 2, -6), s(3, 0.5, 0.5);
    expectMatrix(placed(posed("Spin", 0.0), "Spinner"), trs(t, 0, {0, 1, 0}, s), "key 0");
    expectMatrix(placed(posed("Spin", 0.5), "Spinner"), trs(t, 45, {0, 1, 0}, s), "slerp halfway: 45 degrees");
    expectMatrix(placed(posed("Spin", 0.25), "Spinner"), trs(t, 22.5, {0, 1, 0}, s), "a quarter: 22.5 degrees");
    expectMatrix(placed(posed("Spin", 1.0), "Spinner"), trs(t, 90, {0, 1, 0}, s), "key 1");
    // Key 2 is key 1 negated (the same rotation): the short way between them does not turn at all.
    expectMatrix(placed(posed("Spin", 1.5), "Spinner"), trs(t, 90, {0, 1, 0}, s), "key 1 to its negation");
    // By index, the same animation.
    expectMatrix(placed(posed("1", 0.5), "Spinner"), trs(t, 45, {0, 1, 0}, s), "index 1");
}

TEST(SceneAnimation, CubicSplineFollowsTheHermiteCurveWithTangentsScaledByTheKeyInterval) {
    // Lifter: keys at 0 and 2 s; y from 1 (out-tangent 3) to 2 (in-tangent -1). At s = 0.5 with delta 2:
    // 0.5*1 + 0.125*(2*3) + 0.5*2 + (-0.125)*(2*-1) = 2.5; at s = 0.25: 2.09375. x and z stay 6 (zero tangents).
    expectNear(origin(placed(posed("Cubic", 0.0), "Lifter")), {6, 1, 6}, "key 0");
    expectNear(origin(placed(posed("Cubic", 1.0), "Lifter")), {6, 2.5, 6}, "s = 0.5");
    expectNear(origin(placed(posed("Cubic", 0.5), "Lifter")), {6, 2.09375, 6}, "s = 0.25");
    expectNear(origin(placed(posed("Cubic", 2.0), "Lifter")), {6, 2, 6}, "key 1");
    // Roller: identity to 90 degrees about x with zero tangents: halfway the normalized mix is 45 degrees.
    const glm::dvec3 t(-6, 1, 6), s(0.5, 0.5, 4);
    expectMatrix(placed(posed("Cubic", 1.0), "Roller"), trs(t, 45, {1, 0, 0}, s), "rotation halfway");
    expectMatrix(placed(posed("Cubic", 2.0), "Roller"), trs(t, 90, {1, 0, 0}, s), "rotation at key 1");
}

TEST(SceneAnimation, AllPlaysEveryAnimationAtOnceAndAnUnknownNameIsRefused) {
    const Scene all = posed("all", 1.0);
    expectNear(origin(placed(all, "Mover")), {4, 1, 0}, "Move");
    expectNear(origin(placed(all, "Lifter")), {6, 2.5, 6}, "Cubic");
    Scene scene = boxes();
    AnimationSettings a;
    a.play = "Walk";
    const std::string error = poseScene(scene, a);
    EXPECT_NE(error.find("animation.play \"Walk\""), std::string::npos) << error;
    EXPECT_NE(error.find("0 \"Move\", 1 \"Spin\", 2 \"Cubic\""), std::string::npos) << error;
    a.play = "3";
    EXPECT_NE(poseScene(scene, a), "");
}

TEST(SceneAnimation, TheBoundsHoldEveryPose) {
    const Scene rest = boxes();
    for (double t = 0.0; t <= 2.0; t += 0.05) {
        const Scene scene = posed("all", t);
        for (const Instance& i : scene.instances)
            for (const glm::vec3& p : scene.meshes[std::size_t(i.mesh)].positions) {
                const glm::vec3 w(i.transform * glm::vec4(p, 1.0f));
                for (int c = 0; c < 3; ++c) {
                    EXPECT_GE(w[c], rest.bounds.min[c] - 1e-4f) << "t " << t;
                    EXPECT_LE(w[c], rest.bounds.max[c] + 1e-4f) << "t " << t;
                }
            }
    }
    // The rider reaches y 3.5 at every time, the grower's step to scale 3 only between 1 and 2 s: the bounds are
    // more than the rest pose's.
    Scene unextended = boxes();
    unextended.computeBounds();
    EXPECT_GT(glm::length(rest.bounds.max - rest.bounds.min), glm::length(unextended.bounds.max - unextended.bounds.min));
}

TEST(SceneAnimation, HostileAnimationsAreSkippedWithTheirCauseAndTheRestLoads) {
    struct Case {
        const char* file;
        const char* message;
        std::size_t kept;
    };
    const Case cases[] = {
        {"anim-not-increasing.gltf",
         "animation 1 \"Spin\", channel 0 (node 4 rotation): sampler 0's input (accessor 14) is not strictly "
         "increasing: key 2 at 1 s follows 2 s; the animation is skipped", 2},
        {"anim-count-mismatch.gltf",
         "animation 0 \"Move\", channel 0 (node 1 translation): sampler 0's output (accessor 5) holds 3 elements for "
         "2 keys (one a key); the animation is skipped", 2},
        {"anim-nan-key.gltf", "animation 2 \"Cubic\", channel 0 (node 5 translation): sampler 0's input (accessor 14): "
                              "key 1 is not a finite time; the animation is skipped", 2},
        {"anim-nan-value.gltf", "animation 0 \"Move\", channel 1 (node 3 scale): sampler 1's output (accessor 14): key 1 "
                                "holds nan", 2},
        {"anim-missing-node.gltf", "animation 0 \"Move\", channel 0 (node 99 translation): it targets node 99, which "
                                   "does not exist (the file has 7 nodes); the animation is skipped", 2},
        {"anim-matrix-node.gltf", "animation 1 \"Spin\", channel 0 (node 4 rotation): it targets node 4, which has a "
                                  "matrix", 2},
        {"anim-bad-sampler.gltf", "animation 1 \"Spin\", channel 0 (node 4 rotation): sampler 7 does not exist (the "
                                  "animation has 1); the animation is skipped", 2},
        {"anim-huge-count.gltf", "animation 1 \"Spin\", channel 0 (node 4 rotation): sampler 0: accessor 8 (1073741824 "
                                 "keys) passes the scene's 1024 MiB decode limit", 2},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.file);
        const Scene scene = load(kRegressions + c.file);
        EXPECT_TRUE(hasWarning(scene, c.message)) << (scene.warnings.empty() ? "no warning" : scene.warnings.front());
        EXPECT_EQ(scene.animations.size(), c.kept);
        EXPECT_EQ(scene.invariantError(), "");
    }
}

TEST(SceneAnimation, SkinsAndMorphWeightsAreSaidNotToBePlayed) {
    const std::string models = "/usr/share/assimp/models/glTF2/";
    if (!std::filesystem::exists(models + "simple_skin/simple_skin.gltf"))
        GTEST_SKIP() << "assimp-testmodels is not installed (" << models << ")";
    const Scene skin = load(models + "simple_skin/simple_skin.gltf");
    EXPECT_TRUE(hasWarning(skin, "1 skinned mesh node is not played: skins are drawn in their bind pose"))
        << (skin.warnings.empty() ? "no warning" : skin.warnings.front());
    // Its one animation turns a joint: it is kept (the joint has no mesh, so nothing visible moves).
    EXPECT_EQ(skin.animations.size(), 1u);
    const Scene morph = load(models + "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
    EXPECT_TRUE(hasWarning(morph, "1 morph-target weight channel is not played: meshes keep their base shape"))
        << (morph.warnings.empty() ? "no warning" : morph.warnings.front());
    EXPECT_TRUE(morph.animations.empty());
}

TEST(SceneAnimation, ThePresetRecordsTheAnimationAndTheTime) {
    Settings settings;
    ASSERT_EQ(applySettingOverride(settings, "animation.time=1.25"), "");
    ASSERT_EQ(applySettingOverride(settings, "animation.play=Spin"), "");
    const std::string text = presetToText(settings, "anim", "a pose of animated_boxes", "");
    const PresetLoadResult back = presetFromText(text);
    ASSERT_TRUE(back.settings);
    EXPECT_EQ(back.settings->animation.play, "Spin");
    EXPECT_EQ(back.settings->animation.time, 1.25f);
    EXPECT_TRUE(*back.settings == settings);
    // An index typed bare is its text; an empty name and a negative time are refused naming the key.
    ASSERT_EQ(applySettingOverride(settings, "animation.play=2"), "");
    EXPECT_EQ(settings.animation.play, "2");
    EXPECT_NE(applySettingOverride(settings, "animation.play=\"\"").find("animation.play"), std::string::npos);
    EXPECT_NE(applySettingOverride(settings, "animation.time=-1").find("animation.time"), std::string::npos);
}

TEST(SceneAnimation, LightsAndCamerasFollowTheirAnimatedNode) {
    // animated_boxes with a spot light and a camera under Spinner (translated 1 along its z, scaled 0.5 there), so
    // Spin's turn about y moves both and turns where they look.
    std::ifstream in(kScenes + "animated_boxes.gltf");
    nlohmann::json doc = nlohmann::json::parse(in);
    const std::size_t spinner = 4;
    ASSERT_EQ(doc["nodes"][spinner]["name"], "Spinner");
    doc["nodes"].push_back({{"name", "Lamp"}, {"translation", {0, 0, 1}},
                            {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    doc["nodes"].push_back({{"name", "Eye"}, {"translation", {0, 0, 1}}, {"camera", 0}});
    doc["nodes"][spinner]["children"] = {doc["nodes"].size() - 2, doc["nodes"].size() - 1};
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"] = {{"KHR_lights_punctual",
                          {{"lights", {{{"name", "lamp"}, {"type", "spot"}, {"spot", {{"outerConeAngle", 0.5}}}}}}}}};
    doc["cameras"] = {{{"name", "eye"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
    const std::string path = ::testing::TempDir() + "animated_lamp.gltf";
    std::ofstream(path) << doc.dump();
    const Scene rest = load(path);
    ASSERT_EQ(rest.lights.size(), 1u);
    ASSERT_EQ(rest.cameras.size(), 1u);
    EXPECT_EQ(rest.lights[0].node, nodeNamed(rest, "Lamp"));
    EXPECT_EQ(rest.cameras[0].node, nodeNamed(rest, "Eye"));
    expectNear(glm::dvec3(rest.lights[0].position), {6, 2, -5.5}, "rest lamp");
    expectNear(glm::dvec3(rest.lights[0].direction), {0, 0, -1}, "rest lamp direction");

    const double h = std::sqrt(0.5);
    for (const auto& [time, offset, forward] :
         {std::tuple{1.0, glm::dvec3(0.5, 0, 0), glm::dvec3(-1, 0, 0)},                   // a quarter turn
          std::tuple{0.5, glm::dvec3(0.5 * h, 0, 0.5 * h), glm::dvec3(-h, 0, -h)}}) {   // halfway: an eighth
        Scene scene = load(path);
        AnimationSettings a;
        a.play = "Spin";
        a.time = float(time);
        ASSERT_EQ(poseScene(scene, a), "");
        const std::string at = "t = " + std::to_string(time);
        expectNear(glm::dvec3(scene.lights[0].position), glm::dvec3(6, 2, -6) + offset, ("lamp at " + at).c_str());
        expectNear(glm::dvec3(scene.lights[0].direction), forward, ("lamp direction at " + at).c_str());
        expectNear(scene.cameras[0].position, glm::dvec3(6, 2, -6) + offset, ("eye at " + at).c_str());
        expectNear(scene.cameras[0].forward, forward, ("eye forward at " + at).c_str());
    }
    // "none": the file's pose again.
    Scene none = load(path);
    AnimationSettings still;
    still.play = "none";
    still.time = 1.0f;
    ASSERT_EQ(poseScene(none, still), "");
    expectNear(glm::dvec3(none.lights[0].position), {6, 2, -5.5}, "none");
}
