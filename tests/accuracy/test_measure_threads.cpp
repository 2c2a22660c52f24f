// A measurement does not depend on how many threads ran it: the G-buffer's surface rebuild, the true boundary, the
// distances, causes, counts, texel density, overlays and the soft reference all run on every core, and one thread and
// three give the very same report, bit for bit (textbook and a glTF scene of many small parts, a soft light on both).
#include "gl_fixture.h"
#include "reference/parallel_rows.h"
#include "reference_fixture.h"
#include "scene/scene_source.h"

#include <filesystem>

namespace shadowlab::test {
namespace {

class MeasureThreadsTest : public GlTest {};

constexpr int kWidth = 320;
constexpr int kHeight = 180;

AccuracyReport measureOn(int threads, const Scene& scene, const Settings& settings) {
    const ScopedWorkerCount count(threads);
    EXPECT_EQ(workerCount(), threads);
    AccuracyMeter meter;  // a fresh one: nothing comes from a cache
    const Camera camera = cameraFor(settings.camera, scene, double(kWidth) / kHeight);
    AccuracyReport report = meter.measure(scene, settings, camera, kWidth, kHeight);
    EXPECT_TRUE(report.ok) << report.error;
    return report;
}

void expectSameReport(const AccuracyReport& a, const AccuracyReport& b) {
    EXPECT_EQ(a.acnePercent, b.acnePercent);
    EXPECT_EQ(a.acneSeverity, b.acneSeverity);
    EXPECT_EQ(a.leakPercent, b.leakPercent);
    EXPECT_EQ(a.wrongPercent, b.wrongPercent);
    EXPECT_EQ(a.meanError, b.meanError);
    EXPECT_EQ(a.edgeErrorP95Texels, b.edgeErrorP95Texels);
    EXPECT_EQ(a.edgeErrorP95World, b.edgeErrorP95World);
    EXPECT_EQ(a.edgeErrorP95ScreenPixels, b.edgeErrorP95ScreenPixels);
    const AccuracyCounts &x = a.counts, &y = b.counts;
    EXPECT_EQ(x.measured, y.measured);
    EXPECT_EQ(x.lit, y.lit);
    EXPECT_EQ(x.shadowed, y.shadowed);
    EXPECT_EQ(x.acne, y.acne);
    EXPECT_EQ(x.leak, y.leak);
    EXPECT_EQ(x.wrong, y.wrong);
    EXPECT_EQ(x.mismatched, y.mismatched);
    EXPECT_EQ(x.mismatchedWithinK, y.mismatchedWithinK);
    EXPECT_EQ(x.shadowedNearEdge, y.shadowedNearEdge);
    EXPECT_EQ(x.boundaryPixels, y.boundaryPixels);
    EXPECT_EQ(x.coverageMismatch, y.coverageMismatch);
    EXPECT_TRUE(x.causePixels == y.causePixels);
    EXPECT_EQ(a.texelDensity.pixels, b.texelDensity.pixels);
    EXPECT_EQ(a.texelDensity.p5, b.texelDensity.p5);
    EXPECT_EQ(a.texelDensity.median, b.texelDensity.median);
    EXPECT_EQ(a.texelDensity.p95, b.texelDensity.p95);
    EXPECT_TRUE(a.overlayRgba == b.overlayRgba);
    EXPECT_TRUE(a.causeOverlayRgba == b.causeOverlayRgba);
    EXPECT_TRUE(a.pixelClass == b.pixelClass);
    EXPECT_TRUE(a.pixelCause == b.pixelCause);
    EXPECT_TRUE(a.pixelOnBoundary == b.pixelOnBoundary);
    EXPECT_TRUE(a.pixelSoftVisibility == b.pixelSoftVisibility);
    EXPECT_EQ(a.soft.meanError, b.soft.meanError);
    EXPECT_EQ(a.soft.penumbra.referenceWorld, b.soft.penumbra.referenceWorld);
}

void expectThreadCountIrrelevant(const Scene& scene, Settings settings) {
    settings.lights[0].size = 3.0f;
    settings.reference.softRays = 64;
    const AccuracyReport one = measureOn(1, scene, settings);
    const AccuracyReport three = measureOn(3, scene, settings);
    ASSERT_TRUE(one.ok && three.ok);
    EXPECT_GT(one.counts.boundaryPixels, 0u) << "the view must hold a shadow edge";
    EXPECT_GT(one.counts.mismatched, 0u) << "the view must hold mismatched pixels (distances and causes)";
    expectSameReport(one, three);
}

TEST_F(MeasureThreadsTest, TextbookMeasuresAlikeOnOneThreadAndOnThree) {
    expectThreadCountIrrelevant(loadBuiltin("textbook"), loadShippedPreset("default"));
}

TEST_F(MeasureThreadsTest, FlightHelmetMeasuresAlikeOnOneThreadAndOnThree) {
    const std::string path = std::string(SHADOWLAB_SHARED_SCENES) + "/FlightHelmet_geometry/FlightHelmet.gltf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "the shared scenes are absent (needs " << path << ")";
    SceneLoadResult loaded = loadScene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    expectThreadCountIrrelevant(*loaded.scene, loadShippedPreset("default"));
}

}  // namespace
}  // namespace shadowlab::test
