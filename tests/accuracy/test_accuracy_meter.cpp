// AccuracyMeter on the built-in scenes: the shipped presets measure as their names promise, the reference is reused
// when only the tool's settings change, and bad input or a cancel leave a clear answer.
#include "context/headless_context.h"
#include "gl_fixture.h"
#include "light/depth_bias.h"
#include "reference_fixture.h"

#include <glm/ext/matrix_transform.hpp>

#include <thread>

namespace shadowlab::test {
namespace {

class AccuracyMeterTest : public GlTest {};

constexpr int kWidth = 480;
constexpr int kHeight = 270;

AccuracyReport measurePreset(AccuracyMeter& meter, const Scene& scene, const std::string& preset) {
    const Settings settings = loadShippedPreset(preset);
    const Camera camera = cameraFor(settings.camera, scene, double(kWidth) / kHeight);
    AccuracyReport report = meter.measure(scene, settings, camera, kWidth, kHeight);
    EXPECT_TRUE(report.ok) << report.error;
    saveOverlay(report, "textbook-" + preset);
    return report;
}

long countColour(const AccuracyReport& r, std::uint8_t red, std::uint8_t green, std::uint8_t blue) {
    long n = 0;
    for (std::size_t i = 0; i + 3 < r.overlayRgba.size(); i += 4)
        n += r.overlayRgba[i] == red && r.overlayRgba[i + 1] == green && r.overlayRgba[i + 2] == blue;
    return n;
}

TEST_F(AccuracyMeterTest, AcnePresetHasAcneWellAboveOnePercent) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    const AccuracyReport r = measurePreset(meter, scene, "acne");
    EXPECT_GT(r.acnePercent, 1.0);
    EXPECT_GT(r.counts.lit, 10000u);
    // Every counted acne pixel is red in the overlay.
    EXPECT_EQ(countColour(r, 235, 40, 40), long(r.counts.acne));
}

TEST_F(AccuracyMeterTest, DefaultPresetIsBelowOneTenthPercentAcneAndLeak) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    const AccuracyReport r = measurePreset(meter, scene, "default");
    EXPECT_LT(r.acnePercent, 0.1);
    EXPECT_LT(r.leakPercent, 0.1);
    EXPECT_GT(r.counts.shadowed, 200u) << "the view must show shadows to measure";
    EXPECT_EQ(r.counts.nonFinite, 0u);
    EXPECT_EQ(r.counts.coverageMismatch, 0u) << "G-buffer and the tool's frame must cover the same pixels";
    EXPECT_GT(r.counts.boundaryPixels, 50u);
}

TEST_F(AccuracyMeterTest, PeterPanningPresetLeaksWithoutAcne) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    const AccuracyReport r = measurePreset(meter, scene, "peter-panning");
    EXPECT_GT(r.leakPercent, 10.0);
    EXPECT_LT(r.acnePercent, 0.1);
    EXPECT_GT(r.edgeErrorP95Texels, r.kTexels);
    EXPECT_EQ(countColour(r, 50, 110, 255), long(r.counts.leak));
}

TEST_F(AccuracyMeterTest, ReferenceIsReusedWhenOnlyTheToolsSettingsChange) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    Settings settings = loadShippedPreset("default");
    const Camera camera = cameraFor(settings.camera, scene, double(kWidth) / kHeight);
    const AccuracyReport first = meter.measure(scene, settings, camera, kWidth, kHeight);
    ASSERT_TRUE(first.ok) << first.error;
    EXPECT_FALSE(first.cost.bvhReused);
    EXPECT_FALSE(first.cost.referenceReused);
    EXPECT_GT(first.cost.rays, 10000u);
    EXPECT_GT(first.cost.raysPerSecond, 0.0);

    settings.shadow.slopeScaledDepthBias = 0.0f;
    settings.shadow.normalOffset = 0.0f;
    settings.filter.kernel = 5;
    const AccuracyReport second = meter.measure(scene, settings, camera, kWidth, kHeight);
    ASSERT_TRUE(second.ok) << second.error;
    EXPECT_TRUE(second.cost.bvhReused);
    EXPECT_TRUE(second.cost.referenceReused);
    EXPECT_EQ(second.counts.lit, first.counts.lit);
    EXPECT_EQ(second.kTexels, 3.0) << "PCF 5x5: radius 2 + 1";

    settings.light.direction = glm::vec3(0.3f, -1.0f, 0.2f);
    const AccuracyReport third = meter.measure(scene, settings, camera, kWidth, kHeight);
    ASSERT_TRUE(third.ok) << third.error;
    EXPECT_TRUE(third.cost.bvhReused);
    EXPECT_FALSE(third.cost.referenceReused) << "a new light needs new shadow rays";
    EXPECT_NE(third.counts.shadowed, first.counts.shadowed);
}

TEST_F(AccuracyMeterTest, InvalidSettingsAndCancelGiveAReasonAndKeepWorking) {
    const Scene scene = loadBuiltin("thin-walls");
    AccuracyMeter meter;
    Settings settings;
    const Camera camera = cameraFor(settings.camera, scene, 160.0 / 90.0);
    Settings bad = settings;
    bad.shadow.resolution = 0;
    const AccuracyReport refused = meter.measure(scene, bad, camera, 160, 90);
    EXPECT_FALSE(refused.ok);
    EXPECT_NE(refused.error.find("shadow.resolution"), std::string::npos) << refused.error;

    AccuracyProgress progress;
    progress.cancel = true;
    const AccuracyReport stopped = meter.measure(scene, settings, camera, 160, 90, &progress);
    EXPECT_FALSE(stopped.ok);
    EXPECT_TRUE(stopped.cancelled);

    progress.cancel = false;
    const AccuracyReport done = meter.measure(scene, settings, camera, 160, 90, &progress);
    EXPECT_TRUE(done.ok) << done.error;
    EXPECT_FLOAT_EQ(progress.fraction.load(), 1.0f);
    EXPECT_EQ(progress.stage(), "done");
    EXPECT_EQ(done.overlayRgba.size(), std::size_t(160 * 90 * 4));
}

TEST_F(AccuracyMeterTest, LargeWorldCoordinatesMeasureTheSame) {
    // HARD_CASES 3: the same scene 100 km away. The reference rebuilds points relative to the render origin in double,
    // so the verdicts must not depend on where the scene sits.
    const Settings settings = loadShippedPreset("default");
    AccuracyMeter meter;
    const Scene near = loadBuiltin("textbook");
    const AccuracyReport atOrigin = meter.measure(near, settings, cameraFor(settings.camera, near, double(kWidth) / kHeight), kWidth, kHeight);
    Scene far = loadBuiltin("textbook");
    for (Instance& instance : far.instances)
        instance.transform = glm::translate(glm::mat4(1.0f), glm::vec3(1e5f, 0.0f, 1e5f)) * instance.transform;
    far.computeBounds();
    const AccuracyReport atFar = meter.measure(far, settings, cameraFor(settings.camera, far, double(kWidth) / kHeight), kWidth, kHeight);
    ASSERT_TRUE(atOrigin.ok && atFar.ok) << atOrigin.error << atFar.error;
    saveOverlay(atFar, "textbook-far-away");
    EXPECT_NEAR(double(atFar.counts.lit), double(atOrigin.counts.lit), 0.002 * double(atOrigin.counts.lit));
    EXPECT_NEAR(double(atFar.counts.shadowed), double(atOrigin.counts.shadowed), 0.02 * double(atOrigin.counts.shadowed));
    EXPECT_LT(atFar.acnePercent, 0.1);
    EXPECT_LT(atFar.leakPercent, 0.1);
    EXPECT_EQ(atFar.counts.nonFinite, 0u);
}

TEST_F(AccuracyMeterTest, SpotLightConeIsCounted) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    Settings settings = loadShippedPreset("default");
    settings.light.type = LightType::Spot;
    settings.light.position = glm::vec3(2.0f, 9.0f, 2.0f);
    settings.light.direction = glm::vec3(-0.2f, -1.0f, -0.2f);
    settings.light.spotConeDeg = 50.0f;
    const AccuracyReport r = meter.measure(scene, settings, cameraFor(settings.camera, scene, double(kWidth) / kHeight), kWidth, kHeight);
    ASSERT_TRUE(r.ok) << r.error;
    saveOverlay(r, "textbook-spot");
    EXPECT_GT(r.counts.outsideCone, 1000u);
    EXPECT_GT(r.counts.lit, 1000u);
    EXPECT_LT(r.acnePercent, 0.1) << "outside the cone the tool is dark too: not acne";
}

TEST_F(AccuracyMeterTest, DepthBiasUnitsMatchTheRenderersBiasAmount) {
    const Scene scene = loadBuiltin("textbook");
    Renderer renderer;
    for (LightType type : {LightType::Directional, LightType::Spot}) {
        for (DepthFormat format : {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F}) {
            Settings settings;
            settings.light.type = type;
            settings.shadow.format = format;
            settings.shadow.depthBias = 1000.0f;
            settings.shadow.slopeScaledDepthBias = 0.0f;
            const View view = renderView(renderer, scene, settings, 64, 64);
            ASSERT_TRUE(view.stats.ok);
            const double perUnit = depthBiasUnitTexels(view.stats.light, format,
                                                       receiverDepths(scene, view.stats.light, view.stats.renderOrigin));
            EXPECT_NEAR(perUnit * 1000.0, view.stats.bias.total.texels, 1e-9 * view.stats.bias.total.texels);
        }
    }
}

TEST_F(AccuracyMeterTest, ASecondHeadlessContextOnAWorkerThreadMeasuresBesideThisOne) {
    const Scene scene = loadBuiltin("fence");
    const Settings settings = loadShippedPreset("default");
    AccuracyReport fromWorker;
    std::string workerError;
    std::thread worker([&] {
        try {
            HeadlessContext context;  // as the editor's accuracy worker does
            AccuracyMeter meter;
            fromWorker = meter.measure(scene, settings, cameraFor(settings.camera, scene, 200.0 / 120.0), 200, 120);
        } catch (const std::exception& e) {
            workerError = e.what();
        }
    });
    worker.join();
    EXPECT_EQ(workerError, "");
    EXPECT_TRUE(fromWorker.ok) << fromWorker.error;

    // This thread's context survived the worker's context ending.
    sharedContext().makeCurrent();
    AccuracyMeter meter;
    const AccuracyReport here = meter.measure(scene, settings, cameraFor(settings.camera, scene, 200.0 / 120.0), 200, 120);
    ASSERT_TRUE(here.ok) << here.error;
    EXPECT_EQ(here.counts.lit, fromWorker.counts.lit);
    EXPECT_EQ(here.counts.acne, fromWorker.counts.acne);
}

}  // namespace
}  // namespace shadowlab::test
