// Only the work a frame needs: the shadow pass is skipped when nothing it depends on changed; refused values keep
// the previous state; variants carry only what is used; casters outside the light's volume are skipped.
#include "gl_fixture.h"

#include "scene/builtin_scenes.h"

#include <glm/ext/matrix_transform.hpp>

#include <algorithm>

namespace shadowlab::test {
namespace {

class FrameWork : public GlTest {};

TEST_F(FrameWork, IdenticalSecondFrameSkipsTheShadowPassAndMatchesPixels) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    const Settings s = loadShippedPreset("default");
    const View first = renderView(renderer, scene, s);
    const View second = renderView(renderer, scene, s);
    EXPECT_TRUE(first.stats.shadowPass.ran);
    EXPECT_EQ(first.stats.shadowPass.reason, "first frame");
    EXPECT_FALSE(second.stats.shadowPass.ran) << second.stats.shadowPass.reason;
    EXPECT_TRUE(second.stats.mainPass.ran);
    EXPECT_EQ(first.rgba, second.rgba);
}

TEST_F(FrameWork, ChangingOneBiasReRunsTheShadowPass) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = loadShippedPreset("default");
    renderView(renderer, scene, s);
    s.lights[0].shadow.depthBias += 1.0f;
    const View changed = renderView(renderer, scene, s);
    EXPECT_TRUE(changed.stats.shadowPass.ran);
    EXPECT_EQ(changed.stats.shadowPass.reason, "shadow.depthBias changed");  // named by the key table
    // Settings that only the main pass reads do not re-run it.
    s.filter.kind = FilterKind::Poisson;
    s.view = ViewMode::Shadow;
    s.sampler.addressMode = AddressMode::Wrap;
    EXPECT_FALSE(renderView(renderer, scene, s).stats.shadowPass.ran);
    s.lights[0].direction.x += 0.01f;
    const View moved = renderView(renderer, scene, s);
    EXPECT_TRUE(moved.stats.shadowPass.ran);
    EXPECT_EQ(moved.stats.shadowPass.reason, "direction changed");
    s.lights[0].shadow.resolution = 1024;
    const View resized = renderView(renderer, scene, s);
    EXPECT_TRUE(resized.stats.shadowMapReallocated);
    EXPECT_EQ(resized.stats.shadowMapResolution, 1024);
}

TEST_F(FrameWork, CameraMotionDoesNotReRenderTheShadowMap) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = loadShippedPreset("default");
    renderView(renderer, scene, s);
    s.camera.autoFrame = false;
    s.camera.position = glm::vec3(12.0f, 5.0f, 3.0f);
    EXPECT_FALSE(renderView(renderer, scene, s).stats.shadowPass.ran);
}

TEST_F(FrameWork, ResolutionAboveTheGpuLimitKeepsThePreviousMapWithAMessage) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = loadShippedPreset("default");
    s.lights[0].shadow.resolution = 1024;
    renderView(renderer, scene, s);
    s.lights[0].shadow.resolution = renderer.glInfo().maxTextureSize * 2;
    RenderTarget target;
    target.resize(64, 64);
    const FrameStats stats = renderer.render(scene, s, cameraFor(s.camera, scene, 1.0), target);
    EXPECT_TRUE(stats.ok);
    EXPECT_EQ(stats.shadowMapResolution, 1024);
    ASSERT_FALSE(stats.warnings.empty());
    EXPECT_NE(stats.warnings[0].find("shadow.resolution"), std::string::npos) << stats.warnings[0];
}

TEST_F(FrameWork, InvalidSettingsDrawNothingAndSayWhy) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = loadShippedPreset("default");
    RenderTarget target;
    target.resize(64, 64);
    s.lights[0].shadow.depthBias = std::nanf("");
    FrameStats stats = renderer.render(scene, s, cameraFor(s.camera, scene, 1.0), target);
    EXPECT_FALSE(stats.ok);
    EXPECT_NE(stats.error.find("shadow.depthBias"), std::string::npos) << stats.error;
    s = loadShippedPreset("default");
    s.lights[0].direction = glm::vec3(0.0f);
    stats = renderer.render(scene, s, cameraFor(s.camera, scene, 1.0), target);
    EXPECT_FALSE(stats.ok);
    EXPECT_NE(stats.error.find("lights.0.direction"), std::string::npos) << stats.error;
}

TEST_F(FrameWork, VariantsCarryOnlyTheFeaturesInUse) {
    Renderer renderer;
    Settings s = loadShippedPreset("default");
    s.filter.kind = FilterKind::Pcf;
    s.filter.kernel = 5;
    s.lights[0].shadow.normalOffset = 0.0f;
    const View textbook = renderView(renderer, loadBuiltin("textbook"), s);
    ASSERT_EQ(textbook.stats.mainVariants.size(), 1u);
    const std::string& variant = textbook.stats.mainVariants[0];
    EXPECT_NE(variant.find("PCF_KERNEL 5"), std::string::npos);
    EXPECT_EQ(variant.find("NORMAL_OFFSET"), std::string::npos);
    EXPECT_EQ(variant.find("ALPHA_MASK"), std::string::npos) << "no masked material in the textbook scene";
    EXPECT_EQ(variant.find("LIGHT_PERSPECTIVE"), std::string::npos);
    EXPECT_EQ(textbook.stats.alphaTestedCasters, 0);
    const View fence = renderView(renderer, loadBuiltin("fence"), s);
    EXPECT_EQ(fence.stats.alphaTestedCasters, 1);
    EXPECT_TRUE(std::any_of(fence.stats.mainVariants.begin(), fence.stats.mainVariants.end(),
                            [](const std::string& v) { return v.find("ALPHA_MASK") != std::string::npos; }));
}

TEST_F(FrameWork, CastersOutsideTheLightsVolumeAreSkipped) {
    Renderer renderer;
    Scene scene = loadBuiltin("textbook");
    Settings s = loadShippedPreset("default");
    s.lights[0].type = LightType::Spot;
    s.lights[0].position = glm::vec3(5.0f, 6.0f, 5.0f);
    s.lights[0].direction = glm::vec3(0.0f, -1.0f, 0.0f);
    s.lights[0].spotConeDeg = 30.0f;  // a narrow cone over open floor: only the floor is inside it
    const View view = renderView(renderer, scene, s);
    EXPECT_GT(view.stats.castersSkipped, 0);
    EXPECT_EQ(view.stats.castersDrawn + view.stats.castersSkipped, int(scene.instances.size()));
}

TEST_F(FrameWork, MirroredInstancesCastTheSameShadowAsTheirOriginals) {
    // HARD_CASES 13: a negative-determinant instance reverses winding; culling must follow it.
    Renderer renderer;
    Scene plain = loadBuiltin("textbook");
    Scene mirrored = plain;
    for (Instance& instance : mirrored.instances)
        instance.transform = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)) * instance.transform;
    // Mirror the scene and the light together: the shadows must mirror exactly.
    for (CullMode cull : {CullMode::Back, CullMode::Front}) {
        Settings s = topDownShadowView(loadShippedPreset("default"));
        s.lights[0].shadow.cullMode = cull;
        const View a = renderView(renderer, plain, s, 200, 200);
        s.lights[0].direction.x = -s.lights[0].direction.x;
        const View b = renderView(renderer, mirrored, s, 200, 200);
        const auto dark = [](int red) { return red < 128; };
        const long darkA = a.countScenePixels(dark), darkB = b.countScenePixels(dark);
        EXPECT_GT(darkA, 200);
        EXPECT_NEAR(double(darkB), double(darkA), 0.02 * darkA) << "cull mode " << int(cull);
    }
}

TEST_F(FrameWork, TimingsAreReportedAndLabelled) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    View view = renderView(renderer, scene, loadShippedPreset("default"));
    renderer.waitForTimings(view.stats);
    ASSERT_TRUE(view.stats.shadowPass.milliseconds.has_value());
    ASSERT_TRUE(view.stats.mainPass.milliseconds.has_value());
    EXPECT_GE(*view.stats.shadowPass.milliseconds, 0.0);
    EXPECT_FALSE(view.stats.timingSource.empty());
    if (renderer.glInfo().softwareRasterizer) EXPECT_NE(view.stats.timingSource.find("CPU"), std::string::npos);
}

}  // namespace
}  // namespace shadowlab::test
