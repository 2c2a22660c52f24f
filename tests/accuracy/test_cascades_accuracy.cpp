// Cascaded shadow maps measured (issue 20, §3): each cascade's numbers and the seams' against the reference; the
// stable fit under camera motion (its cascades re-rendered every frame, no pixel flickers).
#include "accuracy/flicker.h"
#include "gl_fixture.h"
#include "image/image_io.h"
#include "reference_fixture.h"

#include <filesystem>

namespace shadowlab::test {
namespace {

constexpr int kWidth = 480;
constexpr int kHeight = 270;

// The textbook seen from near the floor, looking across it: depth spans every cascade.
struct CascadedTextbook {
    explicit CascadedTextbook(CascadeFit fit, float blendBand = 0.1f) : scene(loadBuiltin("textbook")) {
        settings = loadShippedPreset("default");
        LightSettings& sun = settings.lights[0];
        sun.projection.fit = ProjectionFit::Cascades;
        sun.projection.cascadeCount = 3;
        sun.projection.cascadeFit = fit;
        sun.projection.shadowDistance = 30.0f;
        sun.projection.splitLambda = 0.6f;
        sun.projection.blendBand = blendBand;
        sun.shadow.resolution = 1024;
        settings.camera.autoFrame = false;
        settings.camera.position = {-4.0, 1.2, 9.0};
        settings.camera.target = {1.0, 0.3, -3.0};
        camera = cameraFor(settings.camera, scene, double(kWidth) / kHeight);
    }
    FlickerReport play(MotionKind kind, double step, int frames) {
        Motion motion;
        motion.kind = kind;
        motion.step = step;
        motion.frames = frames;
        return measureFlicker(meter, scene, settings, camera, kWidth, kHeight, motion);
    }
    Scene scene;
    Settings settings;
    Camera camera;
    AccuracyMeter meter;
};

}  // namespace

class CascadesAccuracy : public GlTest {};

TEST_F(CascadesAccuracy, EveryCascadeIsMeasuredAndTheOverallNumbersHold) {
    CascadedTextbook t(CascadeFit::Stable);
    const AccuracyReport r = t.meter.measure(t.scene, t.settings, t.camera, kWidth, kHeight);
    ASSERT_TRUE(r.ok) << r.error;
    saveOverlay(r, "cascades-textbook-stable");
    ASSERT_EQ(r.cascades.cascades.size(), 3u);
    std::size_t held = 0;
    for (const CascadeNumbers& c : r.cascades.cascades) {
        EXPECT_GT(c.measured, 500u) << "cascade " << c.cascade << " holds almost nothing of this view";
        EXPECT_LE(c.acnePercent, 0.5) << "cascade " << c.cascade;
        EXPECT_LE(c.leakPercent, 1.0) << "cascade " << c.cascade;
        held += c.measured;
    }
    // Each cascade's texel is coarser than the one before it.
    for (std::size_t c = 1; c < 3; ++c)
        EXPECT_GT(r.cascades.cascades[c].texelWorldSize, r.cascades.cascades[c - 1].texelWorldSize);
    EXPECT_EQ(held + r.cascades.beyondShadowDistance, r.counts.measured);
    EXPECT_GT(r.cascades.seam.band, 0u);
    EXPECT_LE(r.acnePercent, 0.5);
}

// Stable: the camera moves 1.37 of cascade 0's texels a frame, so every cascade's snapped origin moves and every
// cascade is re-rendered each frame (the check that makes it honest: a kept map cannot flicker), and no pixel
// flickers: the texel grid stays where it was in the world. A point filter (S is 0 or 1) shows any crawl.
TEST_F(CascadesAccuracy, StableFitDoesNotFlickerUnderCameraMotionWhileItsCascadesReRender) {
    CascadedTextbook stable(CascadeFit::Stable, 0.0f);
    stable.settings.filter.kind = FilterKind::Point;
    const AccuracyReport first = stable.meter.measure(stable.scene, stable.settings, stable.camera, kWidth, kHeight);
    ASSERT_TRUE(first.ok) << first.error;
    const FlickerReport s = stable.play(MotionKind::Camera, 1.37 * first.cascades.cascades[0].texelWorldSize, 4);
    ASSERT_TRUE(s.ok) << s.error;
    for (const FlickerPair& pair : s.pairs) {
        EXPECT_GT(pair.shadowViewsRendered, 0u) << "cascades follow the camera";
        EXPECT_EQ(pair.counts.vChanged, 0u) << "both halves of a pair shade the same points";
        EXPECT_GT(pair.counts.measured, 50000u);
    }
    ASSERT_EQ(s.cascadeStepTexels.size(), 3u);
    EXPECT_NEAR(s.cascadeStepTexels[0], 1.37, 1e-9);
    EXPECT_LT(s.cascadeStepTexels[2], s.cascadeStepTexels[0]);  // a coarser cascade: fewer of its texels
    EXPECT_EQ(s.maxFlickerPercent, 0.0);
    const std::filesystem::path dir = std::filesystem::path(SHADOWLAB_TEST_OUTPUT) / "accuracy";
    std::filesystem::create_directories(dir);
    EXPECT_EQ(writePng((dir / "cascades-textbook-stable-flicker.png").string(), s.width, s.height, 4,
                       s.overlayRgba.data(), false),
              "");
}

// Tight: the slice's box in light space moves with the camera, so its texel grid crawls by fractions of a texel and
// shadow edges flip from frame to frame: a sideways step of 0.37 of cascade 0's texel (no cascade's grid keeps up).
// Each pair's first half is the new camera with the previous frame's cascades, so the flicker is the maps' alone (V
// does not change).
TEST_F(CascadesAccuracy, TightFitFlickersUnderSubTexelCameraTranslation) {
    CascadedTextbook tight(CascadeFit::Tight, 0.0f);
    tight.settings.filter.kind = FilterKind::Point;
    const AccuracyReport first = tight.meter.measure(tight.scene, tight.settings, tight.camera, kWidth, kHeight);
    ASSERT_TRUE(first.ok) << first.error;
    const FlickerReport t = tight.play(MotionKind::Camera, 0.37 * first.cascades.cascades[0].texelWorldSize, 4);
    ASSERT_TRUE(t.ok) << t.error;
    ASSERT_EQ(t.cascadeStepTexels.size(), 3u);
    EXPECT_NEAR(t.cascadeStepTexels[0], 0.37, 1e-9);
    std::size_t flips = 0;
    for (const FlickerPair& pair : t.pairs) {
        EXPECT_GT(pair.shadowViewsRendered, 0u);
        EXPECT_EQ(pair.counts.vChanged, 0u);
        EXPECT_GT(pair.counts.flicker, 0u) << "pair " << pair.from << ": the tight fit's grid crawls";
        flips += pair.counts.flicker;
    }
    EXPECT_GT(flips, 15u);  // 28 measured on llvmpipe (15, 8, 5 a pair)
    EXPECT_GT(t.maxFlickerPercent, 0.0);
    const std::filesystem::path dir = std::filesystem::path(SHADOWLAB_TEST_OUTPUT) / "accuracy";
    std::filesystem::create_directories(dir);
    EXPECT_EQ(writePng((dir / "cascades-textbook-tight-flicker.png").string(), t.width, t.height, 4,
                       t.overlayRgba.data(), false),
              "");
}

}  // namespace shadowlab::test
