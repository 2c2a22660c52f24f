// Live accuracy: the GPU counter's numbers for a frame equal the CPU metrics' numbers for the same frame (counts
// exactly, sums and the edge error in world units / screen pixels to float rounding, the edge error in texels
// exactly), for settings that give acne, leak, a coarse map, wide filters and a spot light, after bias and filter
// changes in either order; and remeasure refuses a view whose reference is not cached.
#include "gl_fixture.h"
#include "reference_fixture.h"
#include "scene/scene_source.h"
#include "settings/settings_fields.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab::test {
namespace {

class GpuAccuracyCounterTest : public GlTest {};

constexpr int kWidth = 320;
constexpr int kHeight = 180;

void set(Settings& settings, const std::string& keyEqualsValue) {
    ASSERT_EQ(applySettingOverride(settings, keyEqualsValue), "") << keyEqualsValue;
}

void expectClose(double gpu, double cpu, double relative, const char* what) {
    EXPECT_NEAR(gpu, cpu, relative * std::max(1.0, std::abs(cpu))) << what;
}

// The CPU's numbers for this frame (measure) against the GPU's (remeasure), in the given order.
void expectSameNumbers(AccuracyMeter& meter, const Scene& scene, const Settings& settings, const Camera& camera,
                       bool gpuFirst, const std::string& label) {
    SCOPED_TRACE(label);
    AccuracyReport gpu, cpu;
    if (gpuFirst) gpu = meter.remeasure(scene, settings, camera, kWidth, kHeight);
    cpu = meter.measure(scene, settings, camera, kWidth, kHeight);
    if (!gpuFirst) gpu = meter.remeasure(scene, settings, camera, kWidth, kHeight);
    ASSERT_TRUE(cpu.ok) << cpu.error;
    ASSERT_TRUE(gpu.ok) << gpu.error;
    EXPECT_TRUE(gpu.live);
    EXPECT_FALSE(cpu.live);
    const AccuracyCounts &g = gpu.counts, &c = cpu.counts;
    EXPECT_EQ(g.pixels, c.pixels);
    EXPECT_EQ(g.background, c.background);
    EXPECT_EQ(g.facingAway, c.facingAway);
    EXPECT_EQ(g.outsideCone, c.outsideCone);
    EXPECT_EQ(g.nonFinite, c.nonFinite);
    EXPECT_EQ(g.measured, c.measured);
    EXPECT_EQ(g.lit, c.lit);
    EXPECT_EQ(g.shadowed, c.shadowed);
    EXPECT_EQ(g.acne, c.acne);
    EXPECT_EQ(g.leak, c.leak);
    EXPECT_EQ(g.wrong, c.wrong);
    EXPECT_EQ(g.wrongBeyondK, c.wrongBeyondK);
    EXPECT_EQ(g.mismatched, c.mismatched);
    EXPECT_EQ(g.mismatchedWithinK, c.mismatchedWithinK);
    EXPECT_EQ(g.shadowedNearEdge, c.shadowedNearEdge);
    EXPECT_EQ(g.boundaryPixels, c.boundaryPixels);
    EXPECT_EQ(g.coverageMismatch, c.coverageMismatch);
    EXPECT_EQ(gpu.acnePercent, cpu.acnePercent);
    EXPECT_EQ(gpu.leakPercent, cpu.leakPercent);
    EXPECT_EQ(gpu.wrongPercent, cpu.wrongPercent);
    expectClose(gpu.meanError, cpu.meanError, 1e-9, "mean |S-V|");
    expectClose(gpu.acneSeverity, cpu.acneSeverity, 1e-9, "acne severity");
    EXPECT_EQ(gpu.edgeErrorP95Texels, cpu.edgeErrorP95Texels);
    expectClose(gpu.edgeErrorP95World, cpu.edgeErrorP95World, 1e-5, "edge error, world");
    expectClose(gpu.edgeErrorP95ScreenPixels, cpu.edgeErrorP95ScreenPixels, 1e-5, "edge error, screen pixels");
    EXPECT_EQ(gpu.kTexels, cpu.kTexels);
    EXPECT_EQ(gpu.coarseMapWarning, cpu.coarseMapWarning);
    EXPECT_TRUE(gpu.overlayRgba.empty()) << "a live count reads nothing back per pixel";
    std::printf("%-36s acne %zu leak %zu wrong %zu mismatched %zu (within k %zu) mean %.6f p95 %.3f texels, %.4g world,"
                " %.3f px; probed %zu\n",
                label.c_str(), g.acne, g.leak, g.wrong, g.mismatched, g.mismatchedWithinK, gpu.meanError,
                gpu.edgeErrorP95Texels, gpu.edgeErrorP95World, gpu.edgeErrorP95ScreenPixels, gpu.cost.probedPixels);
}

TEST_F(GpuAccuracyCounterTest, GpuCountsEqualCpuCountsAcrossBiasFilterAndMapChanges) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    Settings settings = loadShippedPreset("default");
    const Camera camera = cameraFor(settings.camera, scene, double(kWidth) / kHeight);
    // No reference yet: refused, with the reason.
    const AccuracyReport before = meter.remeasure(scene, settings, camera, kWidth, kHeight);
    EXPECT_FALSE(before.ok);
    EXPECT_TRUE(before.needsReference);

    expectSameNumbers(meter, scene, settings, camera, false, "default");
    ASSERT_GT(meter.measure(scene, settings, camera, kWidth, kHeight).counts.shadowed, 200u);

    // Acne: many pixels mismatched far from edges, their distances probed for the first time by the GPU path.
    Settings acne = loadShippedPreset("acne");
    const AccuracyReport acneReport = meter.measure(scene, acne, camera, kWidth, kHeight);
    ASSERT_GT(acneReport.acnePercent, 1.0);
    set(acne, "shadow.depthBias=0");
    set(acne, "shadow.slopeScaledDepthBias=0.2");
    expectSameNumbers(meter, scene, acne, camera, true, "acne, smaller bias, GPU first");
    set(acne, "shadow.slopeScaledDepthBias=0.5");
    expectSameNumbers(meter, scene, acne, camera, false, "acne, CPU first");

    Settings panning = loadShippedPreset("peter-panning");
    expectSameNumbers(meter, scene, panning, camera, true, "peter-panning");

    // Filters change k (and what has been probed); wide kernels and Poisson.
    for (const std::string& filter :
         {"filter.kind=pcf", "filter.kind=hardware2x2", "filter.kind=poisson", "filter.kind=point"}) {
        Settings s = settings;
        set(s, filter);
        if (filter == "filter.kind=pcf") set(s, "filter.kernel=9");
        expectSameNumbers(meter, scene, s, camera, true, filter);
    }

    // A coarse map: a new light space (boundary rebuilt and uploaded again), most shadows wrong.
    Settings coarse = settings;
    set(coarse, "shadow.resolution=32");
    expectSameNumbers(meter, scene, coarse, camera, true, "32 texel map");
    const AccuracyReport coarseLive = meter.remeasure(scene, coarse, camera, kWidth, kHeight);
    EXPECT_NE(coarseLive.coarseMapWarning, "");
    EXPECT_GT(coarseLive.counts.wrong, coarseLive.counts.shadowed / 2);

    // The camera moved: no reference for that view.
    Camera moved = camera;
    moved.position.x += 0.5;
    const AccuracyReport refused = meter.remeasure(scene, settings, moved, kWidth, kHeight);
    EXPECT_FALSE(refused.ok);
    EXPECT_TRUE(refused.needsReference);
    EXPECT_NE(refused.error.find("measure it first"), std::string::npos) << refused.error;
    // Nor for another size.
    EXPECT_TRUE(meter.remeasure(scene, settings, camera, kWidth + 2, kHeight).needsReference);
}

TEST_F(GpuAccuracyCounterTest, SpotLightAndALightMove) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    Settings spot = loadShippedPreset("default");
    set(spot, "light.type=spot");
    set(spot, "light.position=[2, 9, 2]");
    set(spot, "light.direction=[-0.2, -1, -0.2]");
    set(spot, "light.spotConeDeg=50");
    const Camera camera = cameraFor(spot.camera, scene, double(kWidth) / kHeight);
    expectSameNumbers(meter, scene, spot, camera, false, "spot");
    ASSERT_GT(meter.remeasure(scene, spot, camera, kWidth, kHeight).counts.outsideCone, 1000u);
    set(spot, "shadow.depthBias=0");
    set(spot, "shadow.slopeScaledDepthBias=0");
    set(spot, "shadow.normalOffset=0");
    expectSameNumbers(meter, scene, spot, camera, true, "spot, no bias");
    ASSERT_GT(meter.remeasure(scene, spot, camera, kWidth, kHeight).counts.acne, 100u);
    // The light moved: the exact visibility is another one.
    set(spot, "light.position=[3, 9, 2]");
    const AccuracyReport moved = meter.remeasure(scene, spot, camera, kWidth, kHeight);
    EXPECT_FALSE(moved.ok);
    EXPECT_TRUE(moved.needsReference);
}

// Real glTF scenes: alpha-tested casters (AlphaBlendModeTest's MASK quads), many small parts (FlightHelmet).
TEST_F(GpuAccuracyCounterTest, SharedScenesCountAlikeOnBothPaths) {
    for (const std::string name : {"AlphaBlendModeTest/AlphaBlendModeTest.gltf",
                                   "FlightHelmet_geometry/FlightHelmet.gltf"}) {
        SCOPED_TRACE(name);
        const std::string path = std::string(SHADOWLAB_SHARED_SCENES) + "/" + name;
        if (!std::filesystem::exists(path)) GTEST_SKIP() << "the shared scenes are absent (needs " << path << ")";
        SceneLoadResult loaded = loadScene(path);
        ASSERT_TRUE(loaded.ok()) << loaded.error;
        const Scene& scene = *loaded.scene;
        AccuracyMeter meter;
        Settings settings = loadShippedPreset("default");
        const Camera camera = cameraFor(settings.camera, scene, double(kWidth) / kHeight);
        expectSameNumbers(meter, scene, settings, camera, false, name + ", default");
        set(settings, "shadow.slopeScaledDepthBias=0.5");
        set(settings, "shadow.normalOffset=0");
        expectSameNumbers(meter, scene, settings, camera, true, name + ", less bias");
        set(settings, "filter.kind=poisson");
        expectSameNumbers(meter, scene, settings, camera, true, name + ", Poisson");
    }
}

}  // namespace
}  // namespace shadowlab::test
