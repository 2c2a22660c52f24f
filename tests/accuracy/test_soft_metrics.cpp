// The soft metrics (version 3) on a constructed S / V pair whose numbers are computed by hand: a 40 x 4 view of a
// floor, one world unit per pixel, V a ramp from 0 at x = 16 to 1 at x = 24, S a hard step at x = 20.
#include "accuracy/soft_metrics.h"

#include <gtest/gtest.h>

#include <vector>

namespace shadowlab {
namespace {

TEST(SoftMetrics, AConstructedPairGivesTheHandComputedNumbers) {
    constexpr int width = 40, height = 4;
    std::vector<float> v, s;
    PixelVector<glm::dvec3> points, normals;  // as SurfaceSamples holds them
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            v.push_back(x <= 16 ? 0.0f : x >= 24 ? 1.0f : float(x - 16) / 8.0f);  // 0.125 a pixel
            float shadow = x < 20 ? 0.0f : 1.0f;
            if (x < 4) shadow = 0.02f;     // light in the umbra: bleeding
            if (x >= 36) shadow = 0.99f;   // a shade on fully lit ground: over-darkening
            s.push_back(shadow);
            points.push_back({double(x), 0.0, double(y)});
            normals.push_back({0.0, 1.0, 0.0});
        }
    }
    std::vector<std::uint8_t> measured(v.size(), 1);
    SoftMetricsInput in;
    in.width = width;
    in.height = height;
    in.measured = &measured;
    in.visibility = &v;
    in.shadowFactor = &s;
    in.points = &points;
    in.normals = &normals;
    in.worldPerTexel = [](std::size_t) { return 0.5; };
    const SoftAccuracy a = computeSoftMetrics(in);

    const SoftCounts& c = a.counts;
    EXPECT_EQ(c.measured, 160u);
    EXPECT_EQ(c.umbra, 68u);     // x = 0..16
    EXPECT_EQ(c.fullyLit, 64u);  // x = 24..39
    EXPECT_EQ(c.penumbra, 28u);
    EXPECT_EQ(c.bleeding, 16u);      // x = 0..3
    EXPECT_EQ(c.overDarkened, 16u);  // x = 36..39
    EXPECT_EQ(c.wrong, 4u);          // x = 20: V 0.5, S 1
    EXPECT_DOUBLE_EQ(a.bleedingPercent, 100.0 * 16.0 / 68.0);
    EXPECT_DOUBLE_EQ(a.overDarkeningPercent, 25.0);
    EXPECT_DOUBLE_EQ(a.wrongPercent, 2.5);
    // Per row: 4 x 0.02 + (0.125 + 0.25 + 0.375) + (0.5 + 0.375 + 0.25 + 0.125) + 4 x (1 - 0.99f), over 40 pixels.
    const double row = 4.0 * double(0.02f) + 0.75 + 1.25 + 4.0 * (1.0 - double(0.99f));
    EXPECT_NEAR(a.meanError, row / 40.0, 1e-9);

    // One true-edge pixel a row (x = 20); profiles along +x. V: 0.1 at x = 16.8, 0.9 at x = 23.2: 6.4 world units.
    // S: 0.1 at 19.1, 0.9 at 19.9: 0.8. Error 0.8 - 6.4 = -5.6 world units; texels of 0.5: 12.8, 1.6, -11.2.
    EXPECT_EQ(c.edgePixels, 4u);
    EXPECT_EQ(c.profiles, 4u);
    const PenumbraWidths& w = a.penumbra;
    EXPECT_NEAR(w.referenceWorld, 6.4, 1e-9);
    EXPECT_NEAR(w.techniqueWorld, 0.8, 1e-9);
    EXPECT_NEAR(w.errorWorld, -5.6, 1e-9);
    EXPECT_NEAR(w.referenceTexels, 12.8, 1e-9);
    EXPECT_NEAR(w.techniqueTexels, 1.6, 1e-9);
    EXPECT_NEAR(w.errorTexels, -11.2, 1e-9);
}

// A profile stops where the surface does: a wall (another normal) right after the edge leaves V's transition
// unfinished, so no width is counted rather than one measured across two surfaces.
TEST(SoftMetrics, AProfileStaysOnItsSurface) {
    constexpr int width = 30, height = 1;
    std::vector<float> v;
    PixelVector<glm::dvec3> points, normals;  // as SurfaceSamples holds them
    for (int x = 0; x < width; ++x) {
        v.push_back(x <= 10 ? 0.0f : x >= 18 ? 1.0f : float(x - 10) / 8.0f);
        points.push_back({double(x), 0.0, 0.0});
        normals.push_back(x < 16 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0));
    }
    std::vector<std::uint8_t> measured(v.size(), 1);
    SoftMetricsInput in;
    in.width = width;
    in.height = height;
    in.measured = &measured;
    in.visibility = &v;
    in.shadowFactor = &v;
    in.points = &points;
    in.normals = &normals;
    const SoftAccuracy a = computeSoftMetrics(in);
    EXPECT_EQ(a.counts.edgePixels, 1u);
    EXPECT_EQ(a.counts.profiles, 0u);
    EXPECT_EQ(a.penumbra.referenceWorld, 0.0);
}

}  // namespace
}  // namespace shadowlab
