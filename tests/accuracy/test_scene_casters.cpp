// What casts (casters.excluded) in the renderer and the reference alike: a city inside a closed sky box
// (tests/data/scenes/sky_box_city.gltf) seen from its street camera. With the box casting, everything inside is
// shadowed; with its node excluded the ground is lit, and the exact reference agrees (no leak, no acne), which it
// could not if the box still blocked its rays.
#include "gl_fixture.h"
#include "reference_fixture.h"
#include "scene/gltf_loader.h"
#include "settings/settings_fields.h"

namespace shadowlab::test {
namespace {

class SceneCastersTest : public GlTest {};

constexpr int kWidth = 320;
constexpr int kHeight = 240;

Scene loadSkyBoxCity() {
    SceneLoadResult r = loadGltfScene(std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/sky_box_city.gltf");
    EXPECT_TRUE(r.scene) << r.error;
    return r.scene ? std::move(*r.scene) : Scene{};
}

Settings streetView(bool skyBoxCasts) {
    Settings s = loadShippedPreset("default");
    EXPECT_EQ(applySettingOverride(s, "camera.sceneCamera=0"), "");  // "Street", inside the box
    if (!skyBoxCasts) EXPECT_EQ(applySettingOverride(s, "casters.excluded=Root/City/SkyBox"), "");
    s.view = ViewMode::Shadow;
    return s;
}

AccuracyReport measureStreet(AccuracyMeter& meter, const Scene& scene, const Settings& s, const std::string& name) {
    const Camera camera = cameraFor(s.camera, scene, double(kWidth) / kHeight);
    AccuracyReport r = meter.measure(scene, s, camera, kWidth, kHeight);
    EXPECT_TRUE(r.ok) << r.error;
    saveOverlay(r, name);
    return r;
}

// A ground point in front of the tower, away from its shadow (the light travels toward -x, -z).
const glm::dvec3 kOpenGround(4.0, 0.0, 6.0);

TEST_F(SceneCastersTest, ExcludedSkyBoxLetsTheGroundBeLitInRenderAndReference) {
    const Scene scene = loadSkyBoxCity();
    Renderer renderer;
    AccuracyMeter meter;

    // The box casts: the street is dark, and the reference says so too.
    const Settings boxed = streetView(true);
    const View dark = renderView(renderer, scene, boxed, kWidth, kHeight);
    saveView(dark, "sky-box-casting");
    ASSERT_TRUE(dark.stats.ok) << dark.stats.error;
    EXPECT_LT(dark.meanRedAround(kOpenGround, 3), 40.0);
    const AccuracyReport boxedReport = measureStreet(meter, scene, boxed, "sky-box-casting");
    EXPECT_GT(boxedReport.counts.measured, 10000u);
    EXPECT_LT(double(boxedReport.counts.lit), 0.01 * double(boxedReport.counts.measured));

    // Excluded: the ground is lit, the tower still casts, and the reference agrees pixel for pixel.
    const Settings open = streetView(false);
    const View lit = renderView(renderer, scene, open, kWidth, kHeight);
    saveView(lit, "sky-box-excluded");
    ASSERT_TRUE(lit.stats.ok) << lit.stats.error;
    EXPECT_GT(lit.meanRedAround(kOpenGround, 3), 200.0);
    EXPECT_GT(lit.stats.views.front().castersDrawn, 0);
    const AccuracyReport openReport = measureStreet(meter, scene, open, "sky-box-excluded");
    EXPECT_GT(double(openReport.counts.lit), 0.5 * double(openReport.counts.measured));
    EXPECT_GT(openReport.counts.shadowed, 200u) << "the tower's shadow";
    EXPECT_LT(openReport.acnePercent, 0.5);
    EXPECT_LT(openReport.leakPercent, 0.5);
}

}  // namespace
}  // namespace shadowlab::test
