// Issue 14, reversed-Z (lights.N.shadow.reversedZ): the map stores near 1 and far 0, compares GEQUAL and negates the
// polygon offset, yet a user sees the same shadows: on every built-in and ../shared scene the accuracy numbers agree
// with the normal convention, the border keeps its "lit outside" meaning, and the bias keys push the same way.
#include "accuracy/light_accuracy.h"
#include "gl_fixture.h"
#include "reference_fixture.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "settings/settings_fields.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace shadowlab::test {
namespace {

class ReversedZ : public GlTest {};

void set(Settings& s, const std::string& keyValue) { ASSERT_EQ(applySettingOverride(s, keyValue), "") << keyValue; }

// Every light of the settings in one convention.
Settings inConvention(Settings s, bool reversed) {
    for (LightSettings& light : s.lights) light.shadow.reversedZ = reversed;
    return s;
}

// The preset a built-in scene is shown with: its own when one is shipped (room, courtyard), else the default.
Settings presetFor(const std::string& scene) {
    const std::filesystem::path own = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "presets" / (scene + ".json");
    return loadShippedPreset(std::filesystem::exists(own) ? scene : "default");
}

AccuracyNumbers measureAll(AccuracyMeter& meter, const Scene& scene, const Settings& s, int w, int h,
                           const std::string& overlay = "") {
    const Camera camera = cameraFor(s.camera, scene, double(w) / h);
    const ManyLightsReport r = measureLights(meter, scene, s, camera, w, h);
    EXPECT_TRUE(r.ok) << r.error;
    if (!overlay.empty() && r.ok) {
        AccuracyReport picture;
        picture.ok = true;
        picture.width = r.width;
        picture.height = r.height;
        picture.overlayRgba = r.overlayRgba;
        saveOverlay(picture, overlay);
    }
    return r.whole;
}

void expectSameMasks(const std::string& name, const Scene& scene, const Settings& preset, int w, int h) {
    AccuracyMeter meter;
    Settings normal = inConvention(preset, false);
    for (LightSettings& light : normal.lights) light.shadow.format = DepthFormat::D32F;
    const AccuracyNumbers a = measureAll(meter, scene, normal, w, h, name + "-normal-z");
    const AccuracyNumbers b = measureAll(meter, scene, inConvention(normal, true), w, h, name + "-reversed-z");
    std::printf("%-22s d32f  normal: acne %.3f%% leak %.3f%% wrong %.3f%%  reversed: acne %.3f%% leak %.3f%% wrong %.3f%%\n",
                name.c_str(), a.acnePercent, a.leakPercent, a.wrongPercent, b.acnePercent, b.leakPercent,
                b.wrongPercent);
    EXPECT_GT(a.counts.measured, 0u) << name;
    EXPECT_NEAR(a.wrongPercent, b.wrongPercent, 0.1) << name;
    EXPECT_NEAR(a.acnePercent, b.acnePercent, 0.1) << name;
    EXPECT_NEAR(a.leakPercent, b.leakPercent, 0.1) << name;
}

TEST_F(ReversedZ, EveryBuiltinSceneShowsTheSameShadowsInBothConventions) {
    for (const std::string& name : builtinSceneNames()) {
        SCOPED_TRACE(name);
        expectSameMasks(name, loadBuiltin(name), presetFor(name), 320, 180);
    }
}

TEST_F(ReversedZ, EverySharedSceneShowsTheSameShadowsInBothConventions) {
    const std::filesystem::path root(SHADOWLAB_SHARED_SCENES);
    if (!std::filesystem::is_directory(root)) GTEST_SKIP() << "the shared scenes folder " << root << " is absent";
    int scenes = 0;
    for (const auto& folder : std::filesystem::directory_iterator(root)) {
        if (!folder.is_directory()) continue;
        for (const auto& file : std::filesystem::directory_iterator(folder.path())) {
            if (file.path().extension() != ".gltf") continue;
            SCOPED_TRACE(file.path().string());
            SceneLoadResult loaded = loadScene(file.path().string());
            ASSERT_TRUE(loaded.ok()) << loaded.error;
            expectSameMasks(file.path().stem().string(), *loaded.scene, loadShippedPreset("default"), 320, 180);
            ++scenes;
        }
    }
    EXPECT_GE(scenes, 1);
}

TEST_F(ReversedZ, APointLightInTheRoomCastsTheSameInBothConventions) {
    const Scene room = loadBuiltin("room");
    Settings s = presetFor("room");
    ASSERT_EQ(s.lights[0].type, LightType::Point);
    expectSameMasks("room-point", room, s, 320, 240);
    // The picture too: the same shadow factor at almost every pixel.
    Renderer renderer;
    Settings view = topDownShadowView(s);
    const View normal = renderView(renderer, room, inConvention(view, false), 240, 180);
    const View reversed = renderView(renderer, room, inConvention(view, true), 240, 180);
    saveView(reversed, "room-point-reversed-z");
    long differ = 0;
    for (std::size_t i = 0; i < normal.rgba.size(); i += 4) differ += std::abs(int(normal.rgba[i]) - int(reversed.rgba[i])) > 64;
    EXPECT_LT(double(differ) / double(normal.rgba.size() / 4), 0.002) << differ << " pixels differ";
}

// A receiver outside the light's volume with border addressing: lit in both conventions (sampler.borderDepth 1 means
// "lit outside" whatever the map stores), and shadowed in both with borderDepth 0.
TEST_F(ReversedZ, TheBorderKeepsItsMeaning) {
    const Scene scene = loadBuiltin("textbook");
    Settings s = topDownShadowView(loadShippedPreset("default"));
    // A manual ortho volume 4 wide around the origin: floor points farther than 2 from it lie outside the map.
    set(s, "lights.0.direction=0,-1,0");
    set(s, "lights.0.projection.autoFit=false");
    set(s, "lights.0.projection.orthoSize=4");
    set(s, "lights.0.projection.near=0.01");
    set(s, "lights.0.projection.far=60");
    set(s, "sampler.addressMode=border");
    const glm::dvec3 outside{6.0, 0.0, 6.0};
    for (const float border : {1.0f, 0.0f}) {
        s.sampler.borderDepth = border;
        for (const bool reversed : {false, true}) {
            SCOPED_TRACE(std::string(reversed ? "reversed" : "normal") + " border " + std::to_string(border));
            Renderer renderer;
            const View view = renderView(renderer, scene, inConvention(s, reversed), 320, 240);
            ASSERT_TRUE(view.stats.ok) << view.stats.error;
            if (border == 1.0f) EXPECT_GT(view.meanRedAround(outside, 2), 215.0);
            else EXPECT_LT(view.meanRedAround(outside, 2), 40.0);
        }
    }
}

// With a large DepthBias the shadow detaches the same way in both conventions; with a negative one the lit floor
// acnes the same way. (A bias sign error would swap them: the large bias would acne.)
TEST_F(ReversedZ, TheBiasKeysPushTheSameWayInBothConventions) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    Settings base = loadShippedPreset("default");
    base.lights[0].shadow.normalOffset = 0.0f;
    base.lights[0].shadow.slopeScaledDepthBias = 0.0f;
    Settings detached = base, acne = base;
    detached.lights[0].shadow.depthBias = 1e6f;  // D24: 0.06 of the depth range; contact shadows leak
    acne.lights[0].shadow.depthBias = -2e3f;
    for (DepthFormat format : {DepthFormat::D32F, DepthFormat::D24}) {
        detached.lights[0].shadow.format = acne.lights[0].shadow.format = format;
        // D24's step is fixed; D32F's follows the depth's exponent (smaller reversed near the far end): compare each
        // convention's leak and acne with its own zero-bias baseline.
        const AccuracyNumbers leakN = measureAll(meter, scene, inConvention(detached, false), 320, 180);
        const AccuracyNumbers leakR = measureAll(meter, scene, inConvention(detached, true), 320, 180);
        const AccuracyNumbers acneN = measureAll(meter, scene, inConvention(acne, false), 320, 180);
        const AccuracyNumbers acneR = measureAll(meter, scene, inConvention(acne, true), 320, 180);
        std::printf("%s  large bias: leak %.2f%% / %.2f%% (acne %.2f%% / %.2f%%); negative bias: acne %.2f%% / %.2f%%"
                    " (leak %.2f%% / %.2f%%)  [normal / reversed]\n",
                    format == DepthFormat::D32F ? "d32f" : "d24", leakN.leakPercent, leakR.leakPercent,
                    leakN.acnePercent, leakR.acnePercent, acneN.acnePercent, acneR.acnePercent, acneN.leakPercent,
                    acneR.leakPercent);
        EXPECT_GT(leakN.leakPercent, 1.0);
        EXPECT_GT(leakR.leakPercent, 1.0);
        EXPECT_LT(leakN.acnePercent, 0.1);
        EXPECT_LT(leakR.acnePercent, 0.1);
        EXPECT_GT(acneN.acnePercent, 5.0);
        EXPECT_GT(acneR.acnePercent, 5.0);
        EXPECT_LT(acneN.leakPercent, 0.1);
        EXPECT_LT(acneR.leakPercent, 0.1);
        if (format == DepthFormat::D24) {  // one fixed step: the same bias in depth, so the same picture
            EXPECT_NEAR(leakN.leakPercent, leakR.leakPercent, 0.5);
            EXPECT_NEAR(acneN.acnePercent, acneR.acnePercent, 0.5);
        }
    }
}

}  // namespace
}  // namespace shadowlab::test
