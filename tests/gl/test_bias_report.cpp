// Issue 9, observation 5: the bias the frame report states is the bias the GPU applies. With a manual far plane of
// 1e6 the old report assumed D32F depths in [0.5, 1) and said "0.119 world units, 12 texels" for DepthBias 2; the
// receivers there sit at depth ~1.4e-5, where one D32F step is 2^-40, not 2^-24. Each term is checked against the
// depth the shadow pass really stored (the map read back with and without the bias) and a closed form.
#include "gl_fixture.h"

#include "light/depth_bias.h"

#include <glm/ext/matrix_transform.hpp>

#include <cmath>

namespace shadowlab::test {
namespace {

class BiasReportTest : public GlTest {};

// A 20 x 20 floor, tilted about z by `tiltDeg` (depth then changes along the map's x only).
Scene floorTilted(float tiltDeg) {
    Scene scene;
    scene.name = "floor";
    Mesh m;
    m.name = "floor";
    m.positions = {{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}};
    m.normals.assign(4, glm::vec3(0, 1, 0));
    m.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes.push_back(m);
    scene.instances.push_back({0, glm::rotate(glm::mat4(1.0f), glm::radians(tiltDeg), glm::vec3(0, 0, 1))});
    scene.computeBounds();
    return scene;
}

Settings farPlaneMillion() {
    Settings s = loadShippedPreset("default");
    s.lights[0].direction = {0.0f, -1.0f, 0.0f};
    s.lights[0].projection.autoFit = false;
    s.lights[0].projection.orthoSize = 40.0f;
    s.lights[0].projection.nearPlane = 0.1f;
    s.lights[0].projection.farPlane = 1e6f;
    s.lights[0].shadow.resolution = 256;
    s.lights[0].shadow.depthBias = 0.0f;
    s.lights[0].shadow.slopeScaledDepthBias = 0.0f;
    s.lights[0].shadow.depthBiasClamp = 0.0f;
    return s;
}

// The depth stored at the map's centre texel.
double centreDepth(Renderer& renderer, const Scene& scene, const Settings& s, FrameStats* stats = nullptr) {
    const View view = renderView(renderer, scene, s, 64, 64);
    if (stats) *stats = view.stats;
    const std::vector<float> depth = renderer.shadowMap().readDepth();
    const int n = renderer.shadowMap().resolution();
    return double(depth[std::size_t(n / 2) * std::size_t(n) + std::size_t(n / 2)]);
}

TEST_F(BiasReportTest, ConstantTermIsTheD32FStepAtTheReceiversDepth) {
    Renderer renderer;
    const Scene scene = floorTilted(0.0f);
    Settings s = farPlaneMillion();
    const double unbiased = centreDepth(renderer, scene, s);
    s.lights[0].shadow.depthBias = 1000.0f;
    FrameStats stats;
    const double biased = centreDepth(renderer, scene, s, &stats);
    const double applied = biased - unbiased;

    // Closed form: r = 2^(e - 23), e the exponent of the floor's depth (~1.4e-5, so e = -17 and r = 2^-40).
    int e = 0;
    std::frexp(unbiased, &e);
    const double r = std::ldexp(1.0, e - 1 - 23);
    EXPECT_EQ(e - 1, -17) << unbiased;
    EXPECT_NEAR(applied, 1000.0 * r, 1e-6 * applied) << "what the GPU stored";
    const BiasReport& b = stats.bias;
    ASSERT_TRUE(b.valid);
    // The GPU's float clip space holds depth to one step of ndc near -1: 2^-25 of depth, 0.03 world units here,
    // more than the whole bias (which is why this view has acne). The report says so.
    EXPECT_EQ(b.clipPrecision.depth, std::ldexp(1.0, -25));
    EXPECT_NEAR(b.clipPrecision.world, std::ldexp(1.0, -25) * (1e6 - 0.1), 1e-9);
    EXPECT_NEAR(b.receiverDepthMin, unbiased, 2.0 * b.clipPrecision.depth);
    EXPECT_EQ(b.stepNear, r);
    EXPECT_NEAR(b.constantNear.depth, applied, 1e-6 * applied);
    const double range = 1e6 - 0.1;
    EXPECT_NEAR(b.constantNear.world, applied * range, 1e-6 * applied * range);
    EXPECT_NEAR(b.constantNear.texels, applied * range / (40.0 / 256.0), 1e-6 * applied * range);
    // The old report's figure for DepthBias 2 was 2 x 2^-24 x 1e6 = 0.119 world units; the truth is 1.8e-6.
    s.lights[0].shadow.depthBias = 2.0f;
    renderView(renderer, scene, s, 64, 64);
    const View view = renderView(renderer, scene, s, 64, 64);
    EXPECT_NEAR(view.stats.bias.constantNear.world, 2.0 * r * range, 1e-9);
    EXPECT_LT(view.stats.bias.constantNear.world, 1e-5);
}

TEST_F(BiasReportTest, SlopeTermAndClampAreWhatThePolygonOffsetApplies) {
    Renderer renderer;
    const double tiltDeg = 30.0;
    const Scene scene = floorTilted(float(tiltDeg));
    Settings s = farPlaneMillion();
    const double unbiased = centreDepth(renderer, scene, s);
    s.lights[0].shadow.slopeScaledDepthBias = 100.0f;
    FrameStats stats;
    const double applied = centreDepth(renderer, scene, s, &stats) - unbiased;
    // Closed form: the window depth changes tan(tilt) x texel / (far - near) per texel along x.
    const double texel = 40.0 / 256.0, range = 1e6 - 0.1;
    const double m = std::tan(tiltDeg * M_PI / 180.0) * texel / range;
    // The GPU takes m from float window depths (~3e-8 each): 0.5 % covers that.
    EXPECT_NEAR(applied, 100.0 * m, 5e-3 * applied) << "what the GPU stored";
    EXPECT_NEAR(stats.bias.medianSlope, m, 1e-6 * m);
    EXPECT_NEAR(stats.bias.slope.depth, applied, 5e-3 * applied);
    EXPECT_NEAR(stats.bias.slope.world, 100.0 * std::tan(tiltDeg * M_PI / 180.0) * texel, 1e-3);
    EXPECT_NEAR(stats.bias.slope.texels, 100.0 * std::tan(tiltDeg * M_PI / 180.0), 1e-3 * 100.0);

    if (!renderer.glInfo().polygonOffsetClamp) GTEST_SKIP() << "no glPolygonOffsetClamp on this GL";
    s.lights[0].shadow.depthBiasClamp = float(applied / 4.0);
    const double clamped = centreDepth(renderer, scene, s, &stats) - unbiased;
    EXPECT_NEAR(clamped, double(s.lights[0].shadow.depthBiasClamp), 1e-3 * clamped) << "what the GPU stored";
    EXPECT_NEAR(stats.bias.clamp.depth, clamped, 1e-3 * clamped);
    EXPECT_NEAR(stats.bias.total.depth, clamped, 1e-3 * clamped) << "the clamp limits the total";
}

}  // namespace
}  // namespace shadowlab::test
