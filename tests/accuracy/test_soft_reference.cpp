// The soft reference (reference/soft_visibility.h) against closed-form answers: a thin box over a plane, lit by a
// directional light straight down and by a point light above the box's edge. The 0.1..0.9 width of the penumbra a
// straight edge casts from a uniform disc is a fixed share u* of the full penumbra width w (the disc's chord at u*
// cuts off 10 % of its area), and w = gap x 2 tan(diameter / 2) (directional) or gap x 2 radius / distance (point).
// No GL: the receiver's surface samples are built by hand.
#include "accuracy/soft_metrics.h"
#include "image/image_io.h"
#include "reference/soft_visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

namespace shadowlab {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kBoxBottom = 2.0f;     // the box's underside: gap to the floor
constexpr float kBoxThickness = 0.02f; // thin: its edge is one edge, not two at different heights
constexpr double kGap = kBoxBottom + 0.5 * kBoxThickness;  // for a box, the penumbra's ends come from its bottom and
                                                           // top edges: the full width is (bottom + top) tan = 2 x mid

void addBox(Scene& scene, const glm::vec3& lo, const glm::vec3& hi) {
    Mesh mesh;
    mesh.name = "box";
    for (int i = 0; i < 8; ++i)
        mesh.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    mesh.normals.assign(8, glm::vec3(0.0f, 1.0f, 0.0f));  // the reference reads positions only
    const std::uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& f : faces)
        for (std::uint32_t t : {f[0], f[1], f[2], f[0], f[2], f[3]}) mesh.indices.push_back(t);
    scene.meshes.push_back(std::move(mesh));
    Instance instance;
    instance.mesh = int(scene.meshes.size()) - 1;
    scene.instances.push_back(instance);
}

// A floor (y = 0) and a thin box over it whose edge x = 0 runs along z.
Scene boxOverPlane() {
    Scene scene;
    scene.name = "box over a plane";
    addBox(scene, {-10.0f, -0.01f, -10.0f}, {10.0f, 0.0f, 10.0f});
    addBox(scene, {-4.0f, kBoxBottom, -4.0f}, {0.0f, kBoxBottom + kBoxThickness, 4.0f});
    return scene;
}

// Floor samples (normal up) on a width x height grid from `lo`, `step` apart along x and z.
SurfaceSamples floorSamples(int width, int height, glm::dvec2 lo, double step) {
    SurfaceSamples s;
    s.width = width;
    s.height = height;
    const std::size_t n = std::size_t(width) * std::size_t(height);
    s.draw.assign(n, 0);
    s.instance.assign(n, 0);
    s.triangle.assign(n, 0);
    s.finite.assign(n, 1);
    s.normal.assign(n, glm::dvec3(0.0, 1.0, 0.0));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) s.point.push_back({lo.x + x * step, 0.0, lo.y + y * step});
    return s;
}

// u* of the disc: the chord at distance u* x radius from the centre cuts off 10 % of the area; the 0.1..0.9 width
// of a straight edge's penumbra is then u* x the full width (2 radii).
double discTenNinetyShare() {
    auto cutOff = [](double u) { return (std::acos(u) - u * std::sqrt(1.0 - u * u)) / kPi; };
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 60; ++i) ((cutOff(0.5 * (lo + hi)) > kPenumbraLow) ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
}

constexpr double kSceneRadius = 15.0;

std::vector<PixelClass> hardVerdicts(const EmbreeScene& bvh, const SurfaceSamples& samples,
                                     const ReferenceLight& light) {
    return traceVisibility(bvh, samples, light, kSceneRadius, nullptr).classes;
}

// The 0.1..0.9 width of V along one row of floor samples `step` apart, centred on the edge (x = 0), as the soft
// metrics measure it (a profile reaches kProfileSteps samples each side).
double penumbraWidth(const EmbreeScene& bvh, const ReferenceLight& light, const SoftLight& disc, double step) {
    const SurfaceSamples samples = floorSamples(2 * kProfileSteps + 1, 1, {-kProfileSteps * step, 0.0}, step);
    const std::vector<PixelClass> classes = hardVerdicts(bvh, samples, light);
    const SoftVisibilityResult v = traceSoftVisibility(bvh, samples, classes, light, disc, kSceneRadius, nullptr);
    SoftMetricsInput input;
    input.width = samples.width;
    input.height = samples.height;
    const std::vector<std::uint8_t> measured(samples.size(), 1);
    input.measured = &measured;
    input.visibility = &v.visibility;
    input.shadowFactor = &v.visibility;
    input.points = &samples.point;
    input.normals = &samples.normal;
    const SoftAccuracy a = computeSoftMetrics(input);
    EXPECT_GE(a.counts.profiles, 1u);
    return a.penumbra.referenceWorld;
}

TEST(SoftReference, PenumbraWidensLinearlyWithTheLightSizeAsTheAnalyticWidth) {
    const Scene scene = boxOverPlane();
    const EmbreeScene bvh(scene, glm::dvec3(0.0));
    const double share = discTenNinetyShare();
    ASSERT_NEAR(share, 0.687, 0.01);

    // Directional, straight down: w = gap x 2 tan(diameter / 2).
    ReferenceLight sun;
    sun.direction = {0.0, -1.0, 0.0};
    std::vector<double> widths;
    for (float degrees : {1.0f, 2.0f, 4.0f, 8.0f}) {
        SCOPED_TRACE(std::to_string(degrees) + " degrees");
        LightSettings settings;
        settings.size = degrees;
        const SoftLight disc = softLight(settings, 1024);
        const double w = analyticPenumbraWidth(sun, disc, kGap, 0.0);
        EXPECT_NEAR(w, kGap * 2.0 * std::tan(degrees * kPi / 360.0), 1e-12);
        const double step = share * w / 40.0;  // the transition over 40 samples
        const double measured = penumbraWidth(bvh, sun, disc, step);
        EXPECT_NEAR(measured, share * w, 0.01 * share * w) << "analytic full width " << w;
        widths.push_back(measured);
    }
    // Linear in the size: 8 degrees casts (about) 8 times the 1-degree penumbra.
    EXPECT_NEAR(widths[3] / widths[0], std::tan(4.0 * kPi / 180.0) / std::tan(0.5 * kPi / 180.0), 0.5);

    // A point light 6 above the floor, right above the edge: w = gap x 2 radius / (6 - gap).
    ReferenceLight lamp;
    lamp.type = LightType::Point;
    lamp.position = {0.0, 6.0, 0.0};
    for (float radius : {0.05f, 0.1f, 0.2f, 0.4f}) {
        SCOPED_TRACE("radius " + std::to_string(radius));
        LightSettings settings;
        settings.type = LightType::Point;
        settings.size = radius;
        const SoftLight disc = softLight(settings, 1024);
        const double w = analyticPenumbraWidth(lamp, disc, kGap, 6.0 - kGap);
        EXPECT_NEAR(w, kGap * 2.0 * radius / (6.0 - kGap), 1e-9);
        const double step = share * w / 40.0;
        const double measured = penumbraWidth(bvh, lamp, disc, step);
        EXPECT_NEAR(measured, share * w, 0.01 * share * w) << "analytic full width " << w;
    }
}

TEST(SoftReference, SizeZeroIsTheHardReferenceExactly) {
    const Scene scene = boxOverPlane();
    const EmbreeScene bvh(scene, glm::dvec3(0.0));
    const SurfaceSamples samples = floorSamples(64, 48, {-3.0, -2.0}, 0.1);
    for (LightType type : {LightType::Directional, LightType::Point}) {
        ReferenceLight light;
        light.type = type;
        light.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
        light.position = {0.5, 6.0, 0.3};
        const std::vector<PixelClass> classes = hardVerdicts(bvh, samples, light);
        LightSettings settings;
        settings.type = type;
        const SoftLight hard = softLight(settings, 256);
        ASSERT_FALSE(hard.soft());
        const SoftVisibilityResult v = traceSoftVisibility(bvh, samples, classes, light, hard, kSceneRadius, nullptr);
        std::size_t lit = 0, shadowed = 0;
        for (std::size_t i = 0; i < samples.size(); ++i) {
            ASSERT_EQ(v.visibility[i], isLit(classes[i]) ? 1.0f : 0.0f) << "pixel " << i;
            // Rays toward a disc of radius 0 are the hard ray, every one of them.
            const SoftLight point{0.0, 64};
            ASSERT_EQ(softVisibilityAt(bvh, light, point, samples.point[i], samples.normal[i], kSceneRadius, i),
                      litAt(bvh, light, samples.point[i], samples.normal[i], kSceneRadius) ? 1.0f : 0.0f);
            lit += classes[i] == PixelClass::Lit;
            shadowed += classes[i] == PixelClass::Shadowed;
        }
        EXPECT_GT(lit, 100u);
        EXPECT_GT(shadowed, 100u);
    }
}

TEST(SoftReference, SameResultOnAnyThreadCountAndEveryRun) {
    const Scene scene = boxOverPlane();
    const EmbreeScene bvh(scene, glm::dvec3(0.0));
    const SurfaceSamples samples = floorSamples(160, 120, {-2.0, 2.5}, 0.025);  // around the box's corner (0, 4)
    ReferenceLight light;
    light.direction = glm::normalize(glm::dvec3(0.2, -1.0, 0.1));
    LightSettings settings;
    settings.size = 6.0f;
    const SoftLight disc = softLight(settings, 100);  // not a square: rows of 10 cells
    const std::vector<PixelClass> classes = hardVerdicts(bvh, samples, light);
    const SoftVisibilityResult one = traceSoftVisibility(bvh, samples, classes, light, disc, kSceneRadius, nullptr, 1);
    const SoftVisibilityResult three = traceSoftVisibility(bvh, samples, classes, light, disc, kSceneRadius, nullptr, 3);
    const SoftVisibilityResult again = traceSoftVisibility(bvh, samples, classes, light, disc, kSceneRadius, nullptr, 3);
    EXPECT_EQ(one.threads, 1);
    EXPECT_EQ(three.threads, 3);
    ASSERT_EQ(one.visibility.size(), samples.size());
    EXPECT_TRUE(one.visibility == three.visibility);
    EXPECT_TRUE(three.visibility == again.visibility);
    std::size_t penumbra = 0;
    for (float v : one.visibility) penumbra += v > 0.0f && v < 1.0f;
    EXPECT_GT(penumbra, 500u) << "a 6-degree sun 2 above the floor casts a wide penumbra";

    // To look at: V as a grey image (white = lit), row 0 = the lowest z; the box's corner casts a soft corner.
    std::vector<std::uint8_t> grey;
    for (float v : one.visibility) grey.push_back(std::uint8_t(std::lround(v * 255.0f)));
    std::filesystem::create_directories(SHADOWLAB_TEST_OUTPUT);
    EXPECT_EQ(writePng(std::string(SHADOWLAB_TEST_OUTPUT) + "/soft-visibility-box.png", samples.width, samples.height,
                       1, grey.data(), false),
              "");
}

// softRays walks the strata row by row instead of searching each sample's row: its rays are stratifiedDiscPoint's
// samples, in order, to the bit (a sun straight down: the disc's basis is x and -z, so a ray is (s.x, 1, -s.y)).
TEST(SoftReference, SoftRaysAreTheStratifiedSamplesInOrder) {
    ReferenceLight sun;
    sun.direction = {0.0, -1.0, 0.0};
    for (int n : {64, 100, 250, 256, 1000, 1024}) {
        const SoftLight disc{0.05, n};
        const SoftRays rays = softRays(sun, disc, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0), kSceneRadius, 42);
        ASSERT_EQ(rays.directions.size(), std::size_t(n));
        for (int k = 0; k < n; ++k) {
            const glm::dvec2 s = stratifiedDiscPoint(k, n, 42) * disc.discRadius;
            ASSERT_EQ(rays.directions[std::size_t(k)], glm::vec3(glm::dvec3(s.x, 1.0, -s.y)))
                << "ray " << k << " of " << n;
        }
    }
}

// Every sample of N lies in the unit disc, and each stratum holds one: the sample mean is the disc's centre.
TEST(SoftReference, StratifiedPointsCoverTheDiscEvenly) {
    for (int n : {64, 100, 256, 1000, 1024}) {
        glm::dvec2 sum(0.0);
        int inner = 0;
        for (int k = 0; k < n; ++k) {
            const glm::dvec2 p = stratifiedDiscPoint(k, n, 7);
            ASSERT_LE(glm::length(p), 1.0 + 1e-12);
            sum += p;
            inner += glm::length(p) < std::sqrt(0.5);  // half the disc's area
        }
        EXPECT_LT(glm::length(sum / double(n)), 0.03) << n;
        EXPECT_NEAR(double(inner) / n, 0.5, 0.04) << n;
    }
}

}  // namespace
}  // namespace shadowlab
