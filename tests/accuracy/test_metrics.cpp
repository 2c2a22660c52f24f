// DESIGN.md's measures on hand-made buffers (no GL), the nearest-boundary search, and the probe that finds shadow
// boundaries the view does not show.
#include "accuracy/accuracy_metrics.h"
#include "accuracy/point_tree.h"
#include "accuracy/shadow_boundary.h"
#include "gl_fixture.h"
#include "reference/embree_scene.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>

namespace shadowlab::test {
namespace {

using C = PixelClass;

MetricsResult metricsOf(const std::vector<C>& classes, const std::vector<float>& s,
                        const std::vector<std::uint8_t>& covered, double k, const std::vector<double>& dist) {
    MetricsInput in;
    in.classes = &classes;
    in.shadowFactor = &s;
    in.toolCovered = &covered;
    in.k = k;
    in.distance = [&](std::size_t i) { return dist[i]; };
    in.worldPerTexel = [](std::size_t) { return 0.5; };
    in.worldPerPixel = [](std::size_t) { return 0.25; };
    return computeMetrics(in);
}

TEST(AccuracyMetrics, CountsFollowTheVersion2Definitions) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<C> classes = {C::Lit,      C::Lit,        C::Lit,        C::Lit,         C::Shadowed,
                                    C::Shadowed, C::FacingAway, C::Background, C::OutsideCone, C::NonFinite,
                                    C::Lit};
    const std::vector<float> s = {1.0f, 0.2f, 0.2f, 0.7f, 0.0f, 0.9f, 1.0f, float(nan), 0.8f, 0.0f, 0.0f};
    const std::vector<std::uint8_t> covered = {1, 1, 1, 1, 1, 1, 1, 0, 1, 1, 0};
    const std::vector<double> dist = {9, 5, 1, 5, 9, 4, 0, 0, 0.5, 0, 9};
    const MetricsResult r = metricsOf(classes, s, covered, 2.0, dist);
    const AccuracyCounts& c = r.counts;
    EXPECT_EQ(c.pixels, 11u);
    EXPECT_EQ(c.background, 1u);
    EXPECT_EQ(c.facingAway, 1u);
    EXPECT_EQ(c.outsideCone, 1u);
    EXPECT_EQ(c.nonFinite, 1u);
    EXPECT_EQ(c.coverageMismatch, 1u) << "the last pixel: a surface the tool did not draw";
    EXPECT_EQ(c.measured, 7u);
    EXPECT_EQ(c.lit, 4u);
    EXPECT_EQ(c.shadowed, 3u);
    EXPECT_EQ(c.acne, 2u) << "pixel 1 (S 0.2) and pixel 3 (S 0.7: visibly darkened, version 1 called it faint)";
    EXPECT_EQ(c.leak, 1u);        // pixel 5: shadowed, S 0.9, 4 texels from an edge
    EXPECT_EQ(c.wrong, 4u);       // |S-V| >= 0.5: pixels 1, 2, 5, 8 — edges included
    EXPECT_EQ(c.wrongBeyondK, 2u);  // pixels 1 and 5
    EXPECT_EQ(c.mismatched, 5u);
    EXPECT_EQ(c.mismatchedWithinK, 2u);  // pixel 2 (1 texel) and pixel 8 (outside the cone, 0.5 texel)
    EXPECT_DOUBLE_EQ(r.acnePercent, 50.0);
    EXPECT_NEAR(r.acneSeverity, (0.8 + 0.3) / 2.0, 1e-6);
    EXPECT_NEAR(r.leakPercent, 100.0 / 3.0, 1e-12);
    EXPECT_NEAR(r.wrongPercent, 400.0 / 7.0, 1e-12);
    EXPECT_NEAR(r.meanError, (0.8 + 0.8 + 0.3 + 0.9 + 0.8) / 7.0, 1e-6);
    EXPECT_DOUBLE_EQ(r.edgeErrorP95Texels, 5.0);  // nearest rank of {5, 1, 5, 4, 0.5}
    EXPECT_DOUBLE_EQ(r.edgeErrorP95World, 2.5);   // x 0.5 world units per texel
    EXPECT_DOUBLE_EQ(r.edgeErrorP95ScreenPixels, 10.0);  // / 0.25 world units per pixel
    EXPECT_EQ(r.marks[1], PixelMark::Acne);
    EXPECT_EQ(r.marks[2], PixelMark::AcneNearEdge);
    EXPECT_EQ(r.marks[3], PixelMark::Acne);
    EXPECT_EQ(r.marks[5], PixelMark::Leak);
    EXPECT_EQ(r.marks[8], PixelMark::LeakNearEdge);
    // Without a cause callback: by side and distance; every mismatched pixel has one.
    EXPECT_EQ(r.causes[1], MismatchCause::SelfShadowing);
    EXPECT_EQ(r.causes[2], MismatchCause::NearEdge);
    EXPECT_EQ(r.causes[5], MismatchCause::BiasOverGap);
    EXPECT_EQ(r.causes[0], MismatchCause::None);
    std::size_t explained = 0;
    for (std::size_t n : c.causePixels) explained += n;
    EXPECT_EQ(explained, c.mismatched);
    EXPECT_EQ(c.causeWrong[std::size_t(MismatchCause::NearEdge)], 2u);
}

// Observation 1 of issue 9: stripes at S = 0.6 on a truly lit surface passed version 1 as clean.
TEST(AccuracyMetrics, StripesBetweenHalfAndOneAreAcneAndOneEightBitStepDecides) {
    const std::vector<C> classes(6, C::Lit);
    const std::vector<float> s = {0.6f, 1.0f, 0.6f, 1.0f, 1.0f - 0.5f / 255.0f, 1.0f - 1.5f / 255.0f};
    const std::vector<std::uint8_t> covered(6, 1);
    const MetricsResult r = metricsOf(classes, s, covered, 1.0, std::vector<double>(6, 50.0));
    EXPECT_EQ(r.counts.acne, 3u) << "the two stripes and the pixel darkened by more than one 8-bit step";
    EXPECT_NEAR(r.acnePercent, 50.0, 1e-12);
    EXPECT_EQ(r.counts.wrong, 0u) << "none is wrong by half";
    EXPECT_GT(r.meanError, 0.1);

    const std::vector<C> shadowed = {C::Shadowed, C::Shadowed, C::Shadowed};
    const std::vector<float> t = {0.5f / 255.0f, 1.5f / 255.0f, 0.5f};
    const MetricsResult leak = metricsOf(shadowed, t, {1, 1, 1}, 1.0, {50.0, 50.0, 50.0});
    EXPECT_EQ(leak.counts.leak, 2u);
    EXPECT_EQ(leak.counts.wrong, 1u) << "|S - V| = 0.5 is wrong";

    const std::vector<C> none = {C::Background};
    const MetricsResult empty = metricsOf(none, {0.0f}, {0}, 1.0, {0.0});
    EXPECT_EQ(empty.acnePercent, 0.0);
    EXPECT_EQ(empty.leakPercent, 0.0);
    EXPECT_EQ(empty.wrongPercent, 0.0);
    EXPECT_EQ(empty.edgeErrorP95Texels, 0.0);
}

TEST(AccuracyMetrics, AcceptanceRadiusIsFilterRadiusPlusOneTexel) {
    FilterSettings f;
    f.kind = FilterKind::Point;
    EXPECT_EQ(acceptanceRadiusTexels(f), 1.0);
    f.kind = FilterKind::Pcf;
    f.kernel = 3;
    EXPECT_EQ(acceptanceRadiusTexels(f), 2.0);
    f.kernel = 9;
    EXPECT_EQ(acceptanceRadiusTexels(f), 5.0);
    f.kind = FilterKind::Poisson;
    f.poissonRadius = 3.0f;
    EXPECT_EQ(acceptanceRadiusTexels(f), 5.0);  // radius 3, bilinear taps reach one more texel
}

TEST(AccuracyMetrics, PercentileByNearestRank) {
    std::vector<double> v = {5, 1, 3, 2, 4};
    EXPECT_EQ(percentile(v, 95), 5.0);
    EXPECT_EQ(percentile(v, 50), 3.0);
    EXPECT_EQ(percentile(v, 0), 1.0);
    std::vector<double> none;
    EXPECT_EQ(percentile(none, 95), 0.0);
    // ceil(0.95 n) in integers: 20 values give the 19th, 100 give the 95th (no rounding of 0.95 n upward).
    EXPECT_EQ(nearestRankIndex(20, 95), 18u);
    EXPECT_EQ(nearestRankIndex(100, 95), 94u);
    EXPECT_EQ(nearestRankIndex(1, 95), 0u);
    EXPECT_EQ(nearestRankIndex(21, 95), 19u);
}

TEST(PointTree, NearestDistanceMatchesBruteForce) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-100.0, 100.0);
    std::vector<glm::dvec2> points(1000);
    for (glm::dvec2& p : points) p = {u(random), u(random)};
    // Built in place and then moved, as ShadowBoundary keeps its trees (the tree refers to its points).
    std::array<PointTree, 2> trees;
    trees[1] = PointTree(points);
    const PointTree tree = std::move(trees[1]);
    EXPECT_EQ(tree.size(), points.size());
    for (int q = 0; q < 300; ++q) {
        const glm::dvec2 query(u(random) * 1.5, u(random) * 1.5);
        double best = std::numeric_limits<double>::infinity();
        for (const glm::dvec2& p : points) best = std::min(best, std::hypot(p.x - query.x, p.y - query.y));
        EXPECT_DOUBLE_EQ(tree.nearestDistance(query), best);
    }
    EXPECT_TRUE(std::isinf(PointTree().nearestDistance({0.0, 0.0})));
    EXPECT_TRUE(trees[0].empty());
}

class HiddenBoundary : public GlTest {};

// Lit floor pixels beside the cube's shadow, with the shadow itself not in view (as behind a fold of cloth): the
// visible boundary is empty, yet the true one is a texel away, so the filter's blur there is no acne.
TEST_F(HiddenBoundary, ProbeFindsAShadowEdgeTheViewDoesNotShow) {
    const Scene scene = loadBuiltin("textbook");
    Settings settings;
    settings.lights[0].direction = glm::vec3(0.0f, -1.0f, 0.0f);  // straight down: the cube's shadow is x, z in [-1, 1]
    const glm::dvec3 origin(scene.bounds.center());
    std::string error;
    const std::optional<LightSpace> light = buildLightSpace(settings, scene.bounds, origin, error);
    ASSERT_TRUE(light) << error;
    const double texel = light->texelWorldSize;

    // One row of lit floor samples at 1, 3, 6 and 10 texels beside the shadow's edge x = 1.
    const std::vector<double> texelsFromEdge = {1.0, 3.0, 6.0, 10.0};
    SurfaceSamples samples;
    samples.width = int(texelsFromEdge.size());
    samples.height = 1;
    for (double d : texelsFromEdge) {
        samples.draw.push_back(0);
        samples.point.push_back(glm::dvec3(1.0 + d * texel, 0.0, 0.1) - origin);
        samples.normal.push_back({0.0, 1.0, 0.0});
        samples.finite.push_back(1);
    }
    const EmbreeScene bvh(scene, origin);
    BoundaryProbe probe;
    probe.bvh = &bvh;
    probe.light.direction = light->direction;
    probe.sceneRadius = scene.bounds.radius();
    std::vector<PixelClass> classes;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        ASSERT_TRUE(litAt(bvh, probe.light, samples.point[i], samples.normal[i], probe.sceneRadius));
        classes.push_back(PixelClass::Lit);
    }

    ShadowBoundary withoutProbe(samples, classes, *light, BoundaryProbe{});
    ShadowBoundary withProbe(samples, classes, *light, probe);
    EXPECT_EQ(withProbe.pointCount(), 0u) << "no visible boundary in this view";
    const double k = 5.0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        SCOPED_TRACE(texelsFromEdge[i]);
        EXPECT_GT(withoutProbe.distance(i, k), k);
        const double d = withProbe.distance(i, k);
        if (texelsFromEdge[i] < k) {
            EXPECT_LE(d, k);
            EXPECT_GE(d, texelsFromEdge[i] - 1e-9) << "never nearer than the true edge";
            EXPECT_LE(d, texelsFromEdge[i] + 1.0) << "within the probe's step of the true distance";
        } else {
            EXPECT_GT(d, k);
        }
    }
    EXPECT_EQ(withProbe.probedPixels(), samples.size());
}

}  // namespace
}  // namespace shadowlab::test
