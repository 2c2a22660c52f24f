// The accuracy meter with a light of size > 0: the version-2 numbers stay those of the hard reference (the same as
// for size 0, to the bit), the soft numbers (version 3) come beside them, and size 0 has none.
#include "gl_fixture.h"
#include "reference_fixture.h"

namespace shadowlab::test {
namespace {

class SoftAccuracyMeterTest : public GlTest {};

// Every version-2 number and the counts behind them, exactly.
bool sameNumbers(const AccuracyNumbers& a, const AccuracyNumbers& b) {
    return a.acnePercent == b.acnePercent && a.acneSeverity == b.acneSeverity && a.leakPercent == b.leakPercent &&
           a.wrongPercent == b.wrongPercent && a.meanError == b.meanError &&
           a.edgeErrorP95Texels == b.edgeErrorP95Texels && a.edgeErrorP95World == b.edgeErrorP95World &&
           a.edgeErrorP95ScreenPixels == b.edgeErrorP95ScreenPixels && a.counts.measured == b.counts.measured &&
           a.counts.lit == b.counts.lit && a.counts.shadowed == b.counts.shadowed && a.counts.wrong == b.counts.wrong &&
           a.counts.acne == b.counts.acne && a.counts.leak == b.counts.leak &&
           a.counts.mismatched == b.counts.mismatched && a.counts.causePixels == b.counts.causePixels;
}

TEST_F(SoftAccuracyMeterTest, SizeZeroKeepsVersionTwoAndASizeAddsVersionThree) {
    const Scene scene = loadBuiltin("textbook");
    Settings settings = loadShippedPreset("default");
    constexpr int width = 320, height = 180;
    const Camera camera = cameraFor(settings.camera, scene, double(width) / height);
    AccuracyMeter hardMeter, softMeter;
    const AccuracyReport hard = hardMeter.measure(scene, settings, camera, width, height);
    ASSERT_TRUE(hard.ok) << hard.error;
    EXPECT_FALSE(hard.soft.measured);
    EXPECT_TRUE(hard.pixelSoftVisibility.empty());

    settings.lights[0].size = 4.0f;
    settings.reference.softRays = 64;
    const AccuracyReport soft = softMeter.measure(scene, settings, camera, width, height);
    ASSERT_TRUE(soft.ok) << soft.error;
    EXPECT_TRUE(sameNumbers(hard, soft)) << "the hard numbers must not depend on the light's size";
    EXPECT_TRUE(hard.pixelClass == soft.pixelClass);
    ASSERT_TRUE(soft.soft.measured);
    EXPECT_EQ(soft.soft.metricsVersion, 3);
    EXPECT_EQ(soft.soft.rays, 64);
    EXPECT_EQ(soft.soft.size, 4.0);
    EXPECT_EQ(soft.soft.sizeUnit, "degrees");
    EXPECT_EQ(soft.soft.counts.measured, soft.counts.measured);
    EXPECT_GT(soft.soft.counts.penumbra, 100u) << "a 4-degree sun softens the cube's shadow";
    EXPECT_GT(soft.soft.counts.profiles, 10u);
    EXPECT_GT(soft.soft.penumbra.referenceWorld, 0.0);
    // The hard map draws a penumbra of a few texels at most: narrower than a 4-degree sun's.
    EXPECT_LT(soft.soft.penumbra.errorWorld, 0.0);
    EXPECT_GT(soft.soft.tracedRays, 0u);
    ASSERT_EQ(soft.pixelSoftVisibility.size(), std::size_t(width) * height);

    // The same view again: the soft reference comes from the cache.
    const AccuracyReport again = softMeter.measure(scene, settings, camera, width, height);
    ASSERT_TRUE(again.ok) << again.error;
    EXPECT_EQ(again.soft.tracedRays, 0u);
    EXPECT_TRUE(again.pixelSoftVisibility == soft.pixelSoftVisibility);
    EXPECT_EQ(again.soft.meanError, soft.soft.meanError);
}

}  // namespace
}  // namespace shadowlab::test
