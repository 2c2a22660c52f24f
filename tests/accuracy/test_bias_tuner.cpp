// The bias suggestion: from zero bias it must end with acne within the limit and less leak than Peter Panning.
#include "accuracy/bias_tuner.h"
#include "gl_fixture.h"
#include "reference_fixture.h"

namespace shadowlab::test {
namespace {

class BiasTunerTest : public GlTest {};

Settings zeroBias(Settings s) {
    s.shadow.depthBias = 0.0f;
    s.shadow.slopeScaledDepthBias = 0.0f;
    s.shadow.normalOffset = 0.0f;
    return s;
}

TEST_F(BiasTunerTest, FromZeroBiasEndsWithinTheAcneLimitWithLessLeakThanPeterPanning) {
    for (const std::string name : {"textbook", "grazing"}) {
        SCOPED_TRACE(name);
        const Scene scene = loadBuiltin(name);
        AccuracyMeter meter;
        const Settings start = zeroBias(loadShippedPreset("default"));
        const Camera camera = cameraFor(start.camera, scene, 480.0 / 270.0);
        const AccuracyReport atZero = meter.measure(scene, start, camera, 480, 270);
        ASSERT_TRUE(atZero.ok) << atZero.error;
        EXPECT_GT(atZero.acnePercent, 0.1) << "zero bias must have acne for the test to mean anything";

        AccuracyProgress progress;
        int steps = 0;
        float lastFraction = 0.0f;
        bool fractionRises = true;
        const TuneResult result = tuneBias(meter, scene, start, camera, 480, 270, 0.1, &progress,
                                           [&](const TuneStep&) {
                                               ++steps;
                                               fractionRises = fractionRises && progress.fraction > lastFraction;
                                               lastFraction = progress.fraction;
                                           });
        EXPECT_TRUE(fractionRises) << "the progress bar only moves forward";
        ASSERT_TRUE(result.ok) << result.error;
        EXPECT_TRUE(result.reachedLimit);
        EXPECT_LE(result.report.acnePercent, 0.1);
        EXPECT_EQ(steps, int(result.path.size()));
        EXPECT_GE(result.path.size(), 3u);
        EXPECT_FLOAT_EQ(progress.fraction.load(), 1.0f);
        saveOverlay(result.report, name + "-tuned");

        // The result is what it claims: measured again, the same numbers.
        const AccuracyReport again = meter.measure(scene, result.best, camera, 480, 270);
        EXPECT_DOUBLE_EQ(again.acnePercent, result.report.acnePercent);
        const AccuracyReport panning = meter.measure(scene, loadShippedPreset("peter-panning"), camera, 480, 270);
        EXPECT_LT(again.leakPercent, panning.leakPercent);
        // Only the three searched values change.
        Settings other = result.best;
        other.shadow.depthBias = start.shadow.depthBias;
        other.shadow.slopeScaledDepthBias = start.shadow.slopeScaledDepthBias;
        other.shadow.normalOffset = start.shadow.normalOffset;
        EXPECT_EQ(other, start);
    }
}

TEST_F(BiasTunerTest, SaysWhenNoSettingReachesTheLimit) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    Settings start = zeroBias(loadShippedPreset("default"));
    const Camera camera = cameraFor(start.camera, scene, 160.0 / 90.0);
    const TuneResult refused = tuneBias(meter, scene, start, camera, 160, 90, -1.0);
    EXPECT_FALSE(refused.ok);
    EXPECT_NE(refused.error.find("limit"), std::string::npos);

    // A map smaller than the floor that wraps around: the floor outside it reads the caster and floor depths of the
    // opposite side, far above it. No bias clears that (HARD_CASES 6), so the limit cannot be reached.
    start.projection.autoFit = false;
    start.projection.orthoSize = 8.0f;
    start.projection.nearPlane = 0.01f;
    start.projection.farPlane = 40.0f;
    start.sampler.addressMode = AddressMode::Wrap;
    const TuneResult result = tuneBias(meter, scene, start, camera, 160, 90, 0.1);
    ASSERT_TRUE(result.ok) << result.error;
    EXPECT_FALSE(result.reachedLimit);
    EXPECT_GT(result.report.acnePercent, 1.0);
    for (const TuneStep& step : result.path) {
        EXPECT_FALSE(step.withinLimit);
        EXPECT_GE(step.acnePercent, result.report.acnePercent) << "the least acne is suggested";
    }
}

TEST_F(BiasTunerTest, CancelStopsTheSearch) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    const Settings start = zeroBias(loadShippedPreset("default"));
    AccuracyProgress progress;
    const TuneResult result = tuneBias(meter, scene, start, cameraFor(start.camera, scene, 160.0 / 90.0), 160, 90, 0.1, &progress,
                                       [&](const TuneStep& step) {
                                           if (step.index == 2) progress.cancel = true;
                                       });
    EXPECT_FALSE(result.ok);
    EXPECT_TRUE(result.cancelled);
    EXPECT_EQ(result.path.size(), 2u);
}

}  // namespace
}  // namespace shadowlab::test
