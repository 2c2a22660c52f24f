// Many lights: point-light visibility against hand-computed answers (Embree, no GL), the whole picture's rules on
// synthetic per-light verdicts, and a two-light frame measured light by light equals each light measured alone.
#include "accuracy/accuracy_overlay.h"
#include "accuracy/light_accuracy.h"
#include "accuracy/light_isolation.h"
#include "accuracy/shadow_boundary.h"
#include "gl_fixture.h"
#include "reference_fixture.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace shadowlab::test {
namespace {

// A floor-free scene: one opaque box [-1,1] x [1,2] x [-1,1] (12 triangles), world = render origin.
Scene boxScene() {
    Scene scene;
    scene.name = "box";
    Mesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.positions.emplace_back(i & 1 ? 1.0f : -1.0f, i & 2 ? 2.0f : 1.0f, i & 4 ? 1.0f : -1.0f);
    mesh.normals.assign(8, glm::vec3(0.0f, 1.0f, 0.0f));
    // Each face as two triangles (winding does not matter: the material is opaque and the reference casts both).
    const std::uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    for (const auto& f : faces)
        for (std::uint32_t v : {f[0], f[1], f[2], f[0], f[2], f[3]}) mesh.indices.push_back(v);
    scene.meshes.push_back(mesh);
    scene.instances.push_back(Instance{});
    scene.computeBounds();
    return scene;
}

LightSettings pointAt(glm::vec3 position, float range = 0.0f) {
    LightSettings light;
    light.type = LightType::Point;
    light.position = position;
    light.range = range;
    return light;
}

// Floor points (y = 0, normal up) and one point above the light looking down at it, traced as a 1-row view.
SurfaceSamples floorSamples(const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& normals) {
    SurfaceSamples s;
    s.width = int(points.size());
    s.height = 1;
    s.draw.assign(points.size(), 0);
    s.instance.assign(points.size(), 0);
    s.triangle.assign(points.size(), 0);
    s.point.assign(points.begin(), points.end());
    s.normal.assign(normals.begin(), normals.end());
    s.finite.assign(points.size(), 1);
    return s;
}

TEST(PointLightReference, TheSegmentToTheLightDecidesAsComputedByHand) {
    const Scene scene = boxScene();
    const EmbreeScene bvh(scene, glm::dvec3(0.0));
    const glm::dvec3 up(0.0, 1.0, 0.0);
    const ReferenceLight light = referenceLight(pointAt({0.0f, 5.0f, 0.0f}), glm::dvec3(0.0));
    ASSERT_EQ(light.type, LightType::Point);
    // The box's top edge x = 1 (y = 2) throws its shadow on the floor to x = 1 * 5 / (5 - 2) = 5/3 along +x.
    EXPECT_FALSE(litAt(bvh, light, {0.0, 0.0, 0.0}, up, 5.0)) << "straight under the box";
    EXPECT_FALSE(litAt(bvh, light, {1.5, 0.0, 0.0}, up, 5.0)) << "the segment enters the box's top at x = 0.9";
    EXPECT_FALSE(litAt(bvh, light, {1.6, 0.0, 0.0}, up, 5.0)) << "inside 5/3";
    EXPECT_TRUE(litAt(bvh, light, {1.7, 0.0, 0.0}, up, 5.0)) << "beyond 5/3: the segment passes over the edge";
    EXPECT_TRUE(litAt(bvh, light, {4.0, 0.0, 0.0}, up, 5.0));
    // A directional light straight down lights x = 1.5 (outside the box's footprint): the point light's rays
    // diverge, a directional light's do not.
    ReferenceLight sun;
    sun.direction = -up;
    EXPECT_TRUE(litAt(bvh, sun, {1.5, 0.0, 0.0}, up, 5.0));
    // No cone: a point light lights every direction, up included (a spot pointing down would not).
    EXPECT_TRUE(litAt(bvh, light, {0.0, 9.0, 0.0}, -up, 5.0)) << "a ceiling above the light";
    EXPECT_FALSE(litAt(bvh, light, {0.0, 9.0, 0.0}, up, 5.0)) << "facing away from the light";
}

TEST(PointLightReference, BeyondTheRangeIsNeitherLitNorShadowed) {
    const Scene scene = boxScene();
    const EmbreeScene bvh(scene, glm::dvec3(0.0));
    const glm::dvec3 up(0.0, 1.0, 0.0);
    // Range 6: (4, 0, 0) lies sqrt(41) = 6.40 from the light, (3, 0, 0) sqrt(34) = 5.83.
    const ReferenceLight light = referenceLight(pointAt({0.0f, 5.0f, 0.0f}, 6.0f), glm::dvec3(0.0));
    const SurfaceSamples samples = floorSamples({{0.0, 0.0, 0.0}, {3.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {0.0, 9.0, 0.0}},
                                                {up, up, up, up});
    const VisibilityResult v = traceVisibility(bvh, samples, light, 5.0, nullptr);
    ASSERT_EQ(v.classes.size(), 4u);
    EXPECT_EQ(v.classes[0], PixelClass::Shadowed);
    EXPECT_EQ(v.classes[1], PixelClass::Lit);
    EXPECT_EQ(v.classes[2], PixelClass::OutOfRange);
    EXPECT_EQ(v.classes[3], PixelClass::FacingAway);
    EXPECT_EQ(v.rays, 2u) << "no ray for a point the light does not reach";
    EXPECT_FALSE(isScored(PixelClass::OutOfRange));
    // The same light as a spot pointing down with a 40-degree cone: (3, 0, 0) is 31 degrees off its axis.
    LightSettings spot = pointAt({0.0f, 5.0f, 0.0f}, 6.0f);
    spot.type = LightType::Spot;
    spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    spot.spotConeDeg = 40.0f;
    const VisibilityResult s = traceVisibility(bvh, samples, referenceLight(spot, glm::dvec3(0.0)), 5.0, nullptr);
    EXPECT_EQ(s.classes[0], PixelClass::Shadowed);
    EXPECT_EQ(s.classes[1], PixelClass::OutsideCone);
    EXPECT_EQ(s.classes[2], PixelClass::OutOfRange) << "beyond the range before outside the cone";
}

// A row of floor points x = x0, x0 + step, ... (y = 0, normal up), lit below `edge`, shadowed from it on.
struct FloorRow {
    SurfaceSamples samples;
    std::vector<PixelClass> classes;
};
FloorRow floorRow(double x0, double step, int n, double edge) {
    std::vector<glm::dvec3> points, normals;
    FloorRow row;
    for (int i = 0; i < n; ++i) {
        points.emplace_back(x0 + step * i, 0.0, 0.0);
        normals.emplace_back(0.0, 1.0, 0.0);
        row.classes.push_back(x0 + step * i < edge ? PixelClass::Lit : PixelClass::Shadowed);
    }
    row.samples = floorSamples(points, normals);
    return row;
}

TEST(PointLightBoundary, DistancesAreTexelsOfThePixelsCubeFaceAcrossSeamsToo) {
    LightSpace face;  // what the boundary takes from the light space for a point light: resolution and near plane
    face.resolution = 512;
    face.nearPlane = 0.01;
    BoundaryProbe probe;  // no BVH: visible boundaries only
    probe.light = referenceLight(pointAt({0.0f, 5.0f, 0.0f}), glm::dvec3(0.0));
    // Light 5 above the floor: the floor near it is seen by the -Y face, depth 5, so 1 world unit along x is
    // 512 / 2 / 5 = 51.2 texels. The boundary lies at x = 1.0 (between 0.95 and 1.05); the pixel at x = 2.05 is
    // 1.05 units = 53.76 texels from it.
    const FloorRow near = floorRow(0.05, 0.1, 30, 1.0);
    ShadowBoundary b(near.samples, near.classes, face, probe);
    EXPECT_NEAR(b.visibleDistance(20), 1.05 * 51.2, 1e-4);  // cached as float
    EXPECT_NEAR(b.texelWorldSizeAt({2.05, 0.0, 0.0}), 2.0 * 5.0 / 512.0, 1e-12);
    EXPECT_TRUE(b.onBoundary(9)) << "the lit pixel of the pair";

    // Light 1 above the floor: x = 3 is seen by the +X face (depth 3), the boundary at x = 0.8 by the -Y face. On
    // the +X face's plane the floor point x lies at -1/x (times 256 texels from its centre): the distance across the
    // seam is (1/0.8 - 1/3) x 256 = 234.67 texels, up to the midpoint's curvature (the pair 0.75 / 0.85).
    probe.light = referenceLight(pointAt({0.0f, 1.0f, 0.0f}), glm::dvec3(0.0));
    const FloorRow far = floorRow(0.05, 0.1, 40, 0.8);
    ShadowBoundary seam(far.samples, far.classes, face, probe);
    const double expected = (0.5 * (1.0 / 0.75 + 1.0 / 0.85) - 1.0 / 2.95) * 256.0;
    EXPECT_NEAR(seam.visibleDistance(29), expected, 1e-4) << "x = 2.95 on the +X face";
    EXPECT_NEAR(seam.texelWorldSizeAt({2.95, 0.0, 0.0}), 2.0 * 2.95 / 512.0, 1e-12);
}

// A synthetic per-light report: pixel verdicts as given (lit / shadowed / out of range), S per pixel, marks derived.
AccuracyReport synthetic(const std::vector<PixelClass>& classes, const std::vector<float>& s) {
    AccuracyReport r;
    r.ok = true;
    r.width = int(classes.size());
    r.height = 1;
    r.pixelClass = classes;
    r.pixelShadow = s;
    for (std::size_t i = 0; i < classes.size(); ++i) {
        const bool scored = isScored(classes[i]);
        r.pixelMeasured.push_back(scored);
        const bool lit = isLit(classes[i]);
        const bool wrong = scored && (lit ? s[i] < 0.99f : s[i] > 0.01f);
        r.pixelMark.push_back(!wrong ? PixelMark::None : lit ? PixelMark::Acne : PixelMark::Leak);
        r.pixelCause.push_back(!wrong ? MismatchCause::None : lit ? MismatchCause::SelfShadowing
                                                                   : MismatchCause::BiasOverGap);
        r.pixelOnBoundary.push_back(0);
        r.counts.wrong += scored && std::abs(s[i] - (lit ? 1.0f : 0.0f)) >= 0.5f;
    }
    r.counts.pixels = classes.size();
    r.overlayRgba.assign(classes.size() * 4, 100);
    r.causeOverlayRgba.assign(classes.size() * 4, 100);
    return r;
}

TEST(WholePicture, APixelIsWrongWhenWrongForAnyLightThatReachesIt) {
    using P = PixelClass;
    ManyLightsReport many;
    // Pixel: 0 both right, 1 wrong for light 0 only, 2 wrong for both, 3 wrong for light 1 only, 4 out of light 1's
    // range and right for light 0, 5 out of light 0's range and acne for light 1, 6 reached by neither.
    many.lights.push_back({0, LightType::Directional,
                           synthetic({P::Lit, P::Lit, P::Shadowed, P::Lit, P::Lit, P::OutOfRange, P::OutOfRange},
                                     {1.0f, 0.0f, 1.0f, 1.0f, 1.0f, 0.0f, 0.0f})});
    many.lights.push_back({1, LightType::Point,
                           synthetic({P::Lit, P::Shadowed, P::Lit, P::Shadowed, P::OutOfRange, P::Lit, P::OutOfRange},
                                     {1.0f, 0.0f, 0.2f, 0.9f, 0.0f, 0.3f, 1.0f})});
    combineLights(many);
    const AccuracyCounts& w = many.whole.counts;
    EXPECT_EQ(w.measured, 6u);
    EXPECT_EQ(w.wrong, 4u);  // pixels 1, 2, 3, 5
    EXPECT_GE(w.wrong, std::max(many.lights[0].report.counts.wrong, many.lights[1].report.counts.wrong));
    EXPECT_LE(w.wrong, many.lights[0].report.counts.wrong + many.lights[1].report.counts.wrong);
    EXPECT_EQ(w.acne, 3u);  // 1 (light 0), 2 (light 1), 5 (light 1)
    EXPECT_EQ(w.leak, 2u);  // 2 (light 0), 3 (light 1)
    EXPECT_EQ(w.lit, 6u);
    EXPECT_EQ(w.shadowed, 3u);
    EXPECT_EQ(many.unreached, 1u);
    // Mean of each pixel's largest |S-V|: 0, 1, 1, 0.9, 0, 0.7.
    EXPECT_NEAR(many.whole.meanError, (1.0 + 1.0 + 0.9 + 0.7) / 6.0, 1e-6);
    EXPECT_NEAR(many.whole.wrongPercent, 100.0 * 4.0 / 6.0, 1e-9);
}

// Issue 21: with a sized light among them, the whole picture also has soft numbers: a sized light's soft V, a hard
// light's exact V, each pixel once.
TEST(WholePicture, SoftNumbersCombineASizedLightsSoftVisibilityWithAHardLightsExactOne) {
    using P = PixelClass;
    ManyLightsReport many;
    // Light 0 (sized): soft V 1, 0, 0.5, 1, 0 over pixels 0..4; S 1, 0.3 (bleeding), 0.5, 0.9 (over-darkened), 0.
    AccuracyReport sized = synthetic({P::Lit, P::Shadowed, P::Lit, P::Lit, P::Shadowed}, {1.0f, 0.3f, 0.5f, 0.9f, 0.0f});
    sized.pixelSoftVisibility = {1.0f, 0.0f, 0.5f, 1.0f, 0.0f};
    sized.soft.measured = true;
    sized.soft.penumbra.errorWorld = 0.02;
    // Light 1 (hard): pixel 4 lit (V = 1) but S 0 (wrong, over-darkened); pixel 0 out of its range.
    const AccuracyReport hard =
        synthetic({P::OutOfRange, P::Lit, P::Lit, P::Lit, P::Lit}, {0.0f, 1.0f, 1.0f, 1.0f, 0.0f});
    many.lights.push_back({0, LightType::Directional, sized});
    many.lights.push_back({1, LightType::Point, hard});
    combineLights(many);
    const SoftAccuracy& w = many.wholeSoft;
    ASSERT_TRUE(w.measured);
    EXPECT_EQ(w.counts.measured, 5u);
    EXPECT_EQ(w.counts.umbra, 2u);     // pixels 1, 4 (light 0's umbra)
    EXPECT_EQ(w.counts.bleeding, 1u);  // pixel 1
    EXPECT_EQ(w.counts.fullyLit, 5u);  // 0, 3 by light 0; 1..4 by light 1
    EXPECT_EQ(w.counts.overDarkened, 2u);  // 3 (light 0), 4 (light 1)
    EXPECT_EQ(w.counts.wrong, 1u);         // 4 (light 1: |0 - 1|)
    // Largest |S-V| per pixel: 0, 0.3, 0 (light 0's penumbra matched), 0.1, 1.
    EXPECT_NEAR(w.meanError, (0.3 + 0.1 + 1.0) / 5.0, 1e-6);
    EXPECT_NEAR(w.bleedingPercent, 50.0, 1e-9);
    EXPECT_DOUBLE_EQ(w.penumbra.errorWorld, 0.02);

    // Without a sized light there are no soft numbers.
    many.lights[0].report.soft.measured = false;
    many.lights[0].report.pixelSoftVisibility.clear();
    combineLights(many);
    EXPECT_FALSE(many.wholeSoft.measured);
}

TEST(LightIsolation, TheSceneLightsAreIsolatedAndTunedByTheirIndex) {
    // Two glTF lights with useSceneLights and one settings light: both scene lights take lights[0]'s tuning.
    Scene scene = boxScene();
    SceneLight sun;
    sun.type = SceneLightType::Directional;
    SceneLight bulb;
    bulb.type = SceneLightType::Point;
    bulb.position = glm::vec3(0.0f, 5.0f, 0.0f);
    bulb.range = 6.0f;
    scene.lights = {sun, bulb};
    Settings s;
    s.useSceneLights = true;
    std::string error;
    const std::optional<Settings> one = isolateLight(s, scene, 1, error);
    ASSERT_TRUE(one) << error;
    ASSERT_EQ(one->lights.size(), 1u);
    EXPECT_EQ(one->lights[0].type, LightType::Point);
    EXPECT_FLOAT_EQ(one->lights[0].range, 6.0f);
    EXPECT_FALSE(one->useSceneLights);
    EXPECT_EQ(unmeasurableReason(s, scene, 2), "lights.2: no such light (the scene has 2 lights: 0..1)");
    // Tuning scene light 1 pads the list so scene light 0 keeps the tuning it had.
    ShadowMapSettings tuned;
    tuned.depthBias = 7.0f;
    setLightShadow(s, 1, tuned);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[0].shadow, ShadowMapSettings{});
    EXPECT_EQ(s.lights[1].shadow, tuned);
    EXPECT_EQ(isolateLight(s, scene, 1, error)->lights[0].shadow, tuned);
    EXPECT_EQ(isolateLight(s, scene, 0, error)->lights[0].shadow, ShadowMapSettings{});
}

class LightAccuracyTest : public GlTest {};

// Directional light with too little bias (acne) and a spot light over the same view.
Settings twoLights() {
    Settings s = zeroBias(loadShippedPreset("default"));
    LightSettings spot;
    spot.type = LightType::Spot;
    spot.position = glm::vec3(2.0f, 6.0f, 3.0f);
    spot.direction = glm::vec3(-0.3f, -1.0f, -0.5f);
    spot.shadow.depthBias = 0.0f;
    spot.shadow.slopeScaledDepthBias = 0.2f;
    spot.shadow.normalOffset = 0.0f;
    s.lights.push_back(spot);
    return s;
}

TEST_F(LightAccuracyTest, EachLightOfTwoMeasuresAsThatLightAlone) {
    const Scene scene = loadBuiltin("textbook");
    const Settings both = twoLights();
    const Camera camera = cameraFor(both.camera, scene, 320.0 / 180.0);
    AccuracyMeter meter;
    const ManyLightsReport many = measureLights(meter, scene, both, camera, 320, 180);
    ASSERT_TRUE(many.ok) << many.error;
    ASSERT_EQ(many.lights.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        Settings alone = both;
        alone.lights = {both.lights[i]};
        AccuracyMeter fresh;  // no cache shared with the two-light measurement
        const AccuracyReport a = fresh.measure(scene, alone, camera, 320, 180);
        ASSERT_TRUE(a.ok) << a.error;
        const AccuracyReport& r = many.lights[i].report;
        EXPECT_EQ(many.lights[i].index, i);
        EXPECT_EQ(r.counts.measured, a.counts.measured) << "light " << i;
        EXPECT_EQ(r.counts.lit, a.counts.lit) << "light " << i;
        EXPECT_EQ(r.counts.acne, a.counts.acne) << "light " << i;
        EXPECT_EQ(r.counts.leak, a.counts.leak) << "light " << i;
        EXPECT_EQ(r.counts.wrong, a.counts.wrong) << "light " << i;
        EXPECT_EQ(r.counts.mismatched, a.counts.mismatched) << "light " << i;
        EXPECT_EQ(r.pixelShadow, a.pixelShadow) << "light " << i << ": the same shadow factor pixel for pixel";
        EXPECT_DOUBLE_EQ(r.acnePercent, a.acnePercent) << "light " << i;
    }
    const AccuracyReport& sun = many.lights[0].report;
    const AccuracyReport& spot = many.lights[1].report;
    EXPECT_GT(sun.counts.wrong, 100u) << "zero bias must give the sun acne to count";
    EXPECT_GT(spot.counts.outsideCone, 1000u) << "the spot light lights only part of the view";
    const AccuracyCounts& w = many.whole.counts;
    EXPECT_GE(w.wrong, std::max(sun.counts.wrong, spot.counts.wrong));
    EXPECT_LE(w.wrong, sun.counts.wrong + spot.counts.wrong);
    EXPECT_GE(w.measured, std::max(sun.counts.measured, spot.counts.measured));
    EXPECT_GE(w.acne, std::max(sun.counts.acne, spot.counts.acne));
    EXPECT_LE(w.acne, sun.counts.acne + spot.counts.acne);
    // The union overlay shows a counted colour (acne red, leak blue) wherever any light has acne or leak.
    long red = 0, blue = 0, acneOrLeak = 0;
    for (std::size_t i = 0; i + 3 < many.overlayRgba.size(); i += 4) {
        red += isShadeOf(errorLegend()[0], &many.overlayRgba[i]);  // acne, at any shading
        blue += isShadeOf(errorLegend()[1], &many.overlayRgba[i]);  // leak
        bool counted = false;
        for (const LightAccuracy& light : many.lights) {
            const PixelMark mark = light.report.pixelMark[i / 4];
            counted = counted || mark == PixelMark::Acne || mark == PixelMark::Leak;
        }
        acneOrLeak += counted;
    }
    EXPECT_EQ(red + blue, acneOrLeak);
    EXPECT_LE(red, long(w.acne));
    EXPECT_GE(red, long(std::max(sun.counts.acne, spot.counts.acne)) - long(w.leak));
    AccuracyReport forPicture;
    forPicture.width = many.width;
    forPicture.height = many.height;
    forPicture.overlayRgba = many.overlayRgba;
    saveOverlay(forPicture, "two-lights-union");

    // --light 1: only that light.
    const ManyLightsReport one = measureLights(meter, scene, both, camera, 320, 180, 1);
    ASSERT_TRUE(one.ok) << one.error;
    ASSERT_EQ(one.lights.size(), 1u);
    EXPECT_EQ(one.lights[0].report.counts.wrong, spot.counts.wrong);
    EXPECT_EQ(one.whole.counts.wrong, spot.counts.wrong);
}

// The premise of isolation, checked on the real renderer: the two-light frame's shadow view (the mean S of the lights
// that reach a pixel) is made of exactly the S each light has when it is measured alone.
TEST_F(LightAccuracyTest, TheTwoLightFrameIsMadeOfTheIsolatedShadowFactors) {
    const Scene scene = loadBuiltin("textbook");
    Settings both = twoLights();
    const int w = 320, h = 180;
    const Camera camera = cameraFor(both.camera, scene, double(w) / h);
    AccuracyMeter meter;
    const ManyLightsReport many = measureLights(meter, scene, both, camera, w, h);
    ASSERT_TRUE(many.ok) << many.error;
    both.view = ViewMode::Shadow;
    Renderer renderer;
    RenderTarget target;
    ASSERT_EQ(target.resize(w, h, GL_RGBA32F), "");
    ASSERT_TRUE(renderer.render(scene, both, camera, target).ok);
    std::vector<float> frame(std::size_t(w) * std::size_t(h) * 4);
    glGetTextureImage(target.colorTexture(), 0, GL_RGBA, GL_FLOAT, GLsizei(frame.size() * sizeof(float)), frame.data());
    const AccuracyReport& sun = many.lights[0].report;
    const AccuracyReport& spot = many.lights[1].report;
    long compared = 0, differ = 0, bothReach = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);  // row 0 = top
            if (sun.pixelClass[i] == PixelClass::Background) continue;
            const float shown = frame[(std::size_t(h - 1 - y) * std::size_t(w) + std::size_t(x)) * 4];
            const bool spotReaches = spot.pixelClass[i] != PixelClass::OutsideCone;
            bothReach += spotReaches;
            const float expected = spotReaches ? 0.5f * (sun.pixelShadow[i] + spot.pixelShadow[i]) : sun.pixelShadow[i];
            ++compared;
            differ += std::abs(shown - expected) > 1e-5f;
        }
    EXPECT_GT(bothReach, 2000) << "the spot light must reach part of the view";
    EXPECT_GT(compared, 20000);
    // Only the cone's rim may differ: the reference decides the cone in double, the shader in float.
    EXPECT_LT(differ, compared / 1000) << differ << " of " << compared << " pixels differ";
}

TEST_F(LightAccuracyTest, APointLightMeasuresThroughItsCubeMapAndSkipsWhatItsRangeDoesNotReach) {
    const Scene scene = loadBuiltin("textbook");
    Settings s = loadShippedPreset("default");
    s.lights[0].type = LightType::Point;
    s.lights[0].position = glm::vec3(1.0f, 4.0f, 1.0f);
    s.lights[0].range = 7.0f;
    s.lights[0].shadow.depthBias = 0.6f;
    s.lights[0].shadow.slopeScaledDepthBias = 2.0f;
    s.lights[0].shadow.normalOffset = 1.0f;
    const Camera camera = cameraFor(s.camera, scene, 320.0 / 180.0);
    AccuracyMeter meter;
    const ManyLightsReport many = measureLights(meter, scene, s, camera, 320, 180);
    ASSERT_TRUE(many.ok) << many.error;
    const AccuracyReport& r = many.lights.at(0).report;
    saveOverlay(r, "point-light");
    EXPECT_EQ(many.lights[0].type, LightType::Point);
    // The floor beyond 7 units from the light is not reached: a large share of the view, counted in no number.
    EXPECT_GT(r.counts.outOfRange, 5000u);
    EXPECT_EQ(r.counts.outsideCone, 0u) << "a point light has no cone";
    EXPECT_GT(r.counts.shadowed, 200u) << "the cube and the plank shadow the floor under the light";
    const AccuracyCounts& c = r.counts;
    EXPECT_EQ(c.measured + c.outOfRange + c.facingAway + c.background + c.nonFinite + c.coverageMismatch, c.pixels);
    // The tool's cube map agrees with the exact segments to the light: few wrong pixels, little acne, no leak.
    EXPECT_LT(r.wrongPercent, 0.5);
    EXPECT_LT(r.acnePercent, 1.0);
    EXPECT_LT(r.leakPercent, 0.5);
    // Without bias the cube faces self-shadow: the numbers must see it.
    s.lights[0].shadow.depthBias = 0.0f;
    s.lights[0].shadow.slopeScaledDepthBias = 0.0f;
    s.lights[0].shadow.normalOffset = 0.0f;
    const ManyLightsReport zero = measureLights(meter, scene, s, camera, 320, 180);
    ASSERT_TRUE(zero.ok) << zero.error;
    EXPECT_GT(zero.lights[0].report.acnePercent, 10.0);
    EXPECT_EQ(zero.lights[0].report.counts.outOfRange, c.outOfRange) << "the reference does not depend on the bias";
}

TEST_F(LightAccuracyTest, LightsThatCastNoShadowAreNotMeasuredAndSaySo) {
    const Scene scene = loadBuiltin("textbook");
    Settings s = twoLights();
    s.lights[1].castsShadows = false;
    const Camera camera = cameraFor(s.camera, scene, 160.0 / 90.0);
    AccuracyMeter meter;
    const ManyLightsReport many = measureLights(meter, scene, s, camera, 160, 90);
    ASSERT_TRUE(many.ok) << many.error;
    EXPECT_EQ(many.lights.size(), 1u);
    ASSERT_EQ(many.notMeasured.size(), 1u);
    EXPECT_NE(many.notMeasured[0].reason.find("lights.1.castsShadows"), std::string::npos) << many.notMeasured[0].reason;
    const ManyLightsReport refused = measureLights(meter, scene, s, camera, 160, 90, 5);
    EXPECT_FALSE(refused.ok);
    EXPECT_NE(refused.error.find("lights.5: no such light"), std::string::npos) << refused.error;
    s.lights[0].enabled = false;
    const ManyLightsReport none = measureLights(meter, scene, s, camera, 160, 90);
    EXPECT_FALSE(none.ok);
    EXPECT_NE(none.error.find("no light casts a shadow"), std::string::npos) << none.error;
}

}  // namespace
}  // namespace shadowlab::test
