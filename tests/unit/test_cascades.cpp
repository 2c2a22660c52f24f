// Cascaded shadow maps (views/cascade_views.cpp): the splits, the slices' coverage, the stable fit's fixed texel grid
// under camera motion, the tight fit, the selection and its blend band. No GL.
#include "views/cascade_views.h"
#include "views/shadow_planner.h"
#include "views/view_select.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace shadowlab;

namespace {

Bounds cityBounds() {
    Bounds b;
    b.extend(glm::vec3(-1000.0f, 0.0f, -1000.0f));
    b.extend(glm::vec3(1000.0f, 120.0f, 1000.0f));
    return b;
}

LightSettings sun(int cascades = 4) {
    LightSettings l;
    l.direction = {-0.5f, -1.0f, -0.3f};
    l.shadow.resolution = 1024;
    l.projection.fit = ProjectionFit::Cascades;
    l.projection.cascadeCount = cascades;
    return l;
}

// A camera at eye height looking along `forward` (need not be unit).
ViewCamera eyeCamera(glm::dvec3 eye, glm::dvec3 forward, double aspect = 16.0 / 9.0) {
    ViewCamera c;
    c.eye = eye;
    c.forward = glm::normalize(forward);
    c.right = glm::normalize(glm::cross(c.forward, glm::dvec3(0.0, 1.0, 0.0)));
    c.up = glm::cross(c.right, c.forward);
    c.tanHalfFovY = std::tan(glm::radians(30.0));
    c.aspect = aspect;
    c.nearPlane = 0.1;
    c.farPlane = 2000.0;
    return c;
}

std::vector<ShadowView> cascadesOf(const LightSettings& light, const ViewCamera& camera) {
    std::string error;
    const Bounds bounds = cityBounds();
    const auto views = buildLightViews(light, 0, bounds, bounds.centreOrOrigin(), &camera, error);
    EXPECT_TRUE(views) << error;
    return views ? *views : std::vector<ShadowView>{};
}

// Texel coordinates (in texels from the map's corner) of world point p in a view.
glm::dvec2 texelOf(const LightSpace& space, const glm::dvec3& p) {
    const glm::dvec3 t = space.textureOf(space.viewProjection() * glm::dvec4(p, 1.0));
    return glm::dvec2(t) * double(space.resolution);
}

}  // namespace

TEST(Cascades, PracticalSplitsBlendLogarithmicAndUniform) {
    ViewCamera camera = eyeCamera({0, 1.7, 0}, {0, 0, -1});
    camera.nearPlane = 1.0;
    ProjectionSettings p;
    p.cascadeCount = 4;
    p.shadowDistance = 1000.0f;
    std::string why;
    p.splitLambda = 1.0f;  // logarithmic: 1000^(i/4)
    std::vector<double> far = cascadeFarDepths(p, camera, why);
    ASSERT_EQ(far.size(), 4u) << why;
    EXPECT_NEAR(far[0], std::pow(1000.0, 0.25), 1e-9);
    EXPECT_NEAR(far[1], std::pow(1000.0, 0.5), 1e-9);
    EXPECT_DOUBLE_EQ(far[3], 1000.0);
    p.splitLambda = 0.0f;  // uniform
    far = cascadeFarDepths(p, camera, why);
    EXPECT_NEAR(far[0], 1.0 + 999.0 * 0.25, 1e-9);
    p.shadowDistance = 0.0f;  // the camera's far plane
    EXPECT_DOUBLE_EQ(cascadeFarDepths(p, camera, why).back(), camera.farPlane);
}

TEST(Cascades, ManualSplitsAreUsedAndBadOnesNamed) {
    const ViewCamera camera = eyeCamera({0, 1.7, 0}, {0, 0, -1});
    ProjectionSettings p;
    p.cascadeCount = 3;
    p.shadowDistance = 500.0f;
    p.splits = {20.0f, 90.0f, 0.0f};
    std::string why;
    const std::vector<double> far = cascadeFarDepths(p, camera, why);
    ASSERT_EQ(far.size(), 3u) << why;
    EXPECT_DOUBLE_EQ(far[0], 20.0);
    EXPECT_DOUBLE_EQ(far[1], 90.0);
    EXPECT_DOUBLE_EQ(far[2], 500.0);
    p.splits = {20.0f, 900.0f, 0.0f};  // beyond the shadow distance
    EXPECT_TRUE(cascadeFarDepths(p, camera, why).empty());
    EXPECT_NE(why.find("projection.splits"), std::string::npos) << why;
    p.splits = {};
    p.shadowDistance = 0.05f;  // before the camera's near plane
    EXPECT_TRUE(cascadeFarDepths(p, camera, why).empty());
    EXPECT_NE(why.find("projection.shadowDistance"), std::string::npos) << why;
}

TEST(Cascades, NeedACamera) {
    const Bounds bounds = cityBounds();
    std::string error;
    EXPECT_FALSE(buildLightViews(sun(), 2, bounds, bounds.centreOrOrigin(), nullptr, error));
    EXPECT_NE(error.find("lights.2: projection.fit"), std::string::npos) << error;
}

// Every point of the camera's frustum up to the shadow distance lies inside the view selectView picks for it (and in
// the blend band, inside the next one too), for both fits.
TEST(Cascades, EveryFrustumPointIsInsideTheCascadeThatHoldsIt) {
    for (CascadeFit fit : {CascadeFit::Stable, CascadeFit::Tight}) {
        LightSettings light = sun();
        light.projection.cascadeFit = fit;
        light.projection.shadowDistance = 600.0f;
        light.projection.blendBand = 0.2f;
        const ViewCamera camera = eyeCamera({30, 1.7, 40}, {0.3, -0.05, -1});
        const std::vector<ShadowView> views = cascadesOf(light, camera);
        ASSERT_EQ(views.size(), 4u);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> unit(-1.0, 1.0), depth01(0.0, 1.0);
        int blended = 0;
        for (int k = 0; k < 20000; ++k) {
            const double z = camera.nearPlane + (600.0 - camera.nearPlane) * std::pow(depth01(rng), 3.0);
            const glm::dvec3 p = camera.eye + camera.forward * z +
                                 camera.right * (unit(rng) * camera.tanHalfFovY * camera.aspect * z) +
                                 camera.up * (unit(rng) * camera.tanHalfFovY * z);
            const ViewChoice choice = selectView(views, p);
            ASSERT_GE(choice.view, 0) << "depth " << z;
            for (int v : {choice.view, choice.next}) {
                if (v < 0) continue;
                const glm::dvec2 t = texelOf(views[std::size_t(v)].space, p) / 1024.0;
                EXPECT_TRUE(t.x >= 0.0 && t.x <= 1.0 && t.y >= 0.0 && t.y <= 1.0)
                    << "fit " << int(fit) << " cascade " << v << " misses a point at depth " << z;
            }
            blended += choice.next >= 0;
        }
        EXPECT_GT(blended, 100);  // the band is used
        // Beyond the shadow distance no cascade holds a point: it is lit.
        EXPECT_EQ(selectView(views, camera.eye + camera.forward * 700.0).view, -1);
    }
}

TEST(Cascades, BlendBandFadesIntoTheNextCascade) {
    const std::vector<double> far = {10.0, 40.0, 100.0};
    const std::vector<double> blend = {8.0, 34.0, 100.0};
    EXPECT_EQ(selectCascade(5.0, far, blend).view, 0);
    EXPECT_EQ(selectCascade(5.0, far, blend).next, -1);
    const ViewChoice mid = selectCascade(9.0, far, blend);
    EXPECT_EQ(mid.view, 0);
    EXPECT_EQ(mid.next, 1);
    EXPECT_DOUBLE_EQ(mid.weight, 0.5);
    EXPECT_EQ(selectCascade(10.0, far, blend).view, 0);
    EXPECT_DOUBLE_EQ(selectCascade(10.0, far, blend).weight, 1.0);
    EXPECT_EQ(selectCascade(10.5, far, blend).view, 1);
    EXPECT_EQ(selectCascade(99.0, far, blend).next, -1);  // the last cascade has nothing to fade into
    EXPECT_EQ(selectCascade(101.0, far, blend).view, -1);
}

// The stable fit: camera translation and rotation move no texel edge. A fixed world point's texel coordinate in a
// cascade changes by whole texels only (the grid is fixed in the world), and the cascade's size never changes.
TEST(Cascades, StableFitKeepsTheTexelGridStillUnderCameraMotion) {
    LightSettings light = sun();
    light.projection.shadowDistance = 400.0f;
    const glm::dvec3 probe(12.3456, 0.0, -35.789);
    std::vector<ShadowView> first = cascadesOf(light, eyeCamera({0, 1.7, 0}, {0, 0, -1}));
    ASSERT_EQ(first.size(), 4u);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> step(-3.0, 3.0), turn(-0.4, 0.4);
    glm::dvec3 eye(0, 1.7, 0), forward(0, 0, -1);
    for (int frame = 0; frame < 200; ++frame) {
        eye += glm::dvec3(step(rng), 0.0, step(rng));
        forward = glm::normalize(forward + glm::dvec3(turn(rng), 0.05 * turn(rng), turn(rng)));
        const std::vector<ShadowView> now = cascadesOf(light, eyeCamera(eye, forward));
        ASSERT_EQ(now.size(), 4u);
        for (std::size_t c = 0; c < 4; ++c) {
            EXPECT_DOUBLE_EQ(now[c].space.orthoSize, first[c].space.orthoSize) << "cascade " << c;
            const glm::dvec2 shift = texelOf(now[c].space, probe) - texelOf(first[c].space, probe);
            EXPECT_NEAR(shift.x, std::round(shift.x), 1e-6) << "cascade " << c << " frame " << frame;
            EXPECT_NEAR(shift.y, std::round(shift.y), 1e-6) << "cascade " << c << " frame " << frame;
        }
    }
}

// The tight fit's box is smaller (more texels on screen) and its grid moves by fractions of a texel: what it costs.
TEST(Cascades, TightFitIsSmallerAndItsGridCrawls) {
    LightSettings stable = sun(), tight = sun();
    tight.projection.cascadeFit = CascadeFit::Tight;
    const ViewCamera a = eyeCamera({0, 1.7, 0}, {0, 0, -1}), b = eyeCamera({0.37, 1.7, 0.11}, {0.02, 0, -1});
    const std::vector<ShadowView> s = cascadesOf(stable, a), t = cascadesOf(tight, a), t2 = cascadesOf(tight, b);
    ASSERT_EQ(t.size(), 4u);
    for (std::size_t c = 0; c < 4; ++c) EXPECT_LE(t[c].space.orthoSize, s[c].space.orthoSize) << "cascade " << c;
    const glm::dvec3 probe(5.0, 0.0, -20.0);
    const glm::dvec2 shift = texelOf(t2[1].space, probe) - texelOf(t[1].space, probe);
    EXPECT_GT(std::abs(shift.x - std::round(shift.x)) + std::abs(shift.y - std::round(shift.y)), 1e-3);
}

// Cascades follow the camera: the planner's reason says so, and every cascade of a light shares one map array.
TEST(Cascades, PlannerPutsALightsCascadesInOneArrayAndNamesThem) {
    Settings s;
    s.lights = {sun(3)};
    const Bounds bounds = cityBounds();
    const ViewCamera camera = eyeCamera({0, 1.7, 0}, {0, 0, -1});
    Scene scene;
    scene.bounds = bounds;
    const std::vector<CasterSphere> city = {{glm::dvec3(0.0), 5000.0, true}};  // in every cascade's volume
    const ShadowPlan plan =
        planShadowViews({scene, s, bounds.centreOrOrigin(), &camera, std::nullopt, city, 0, 16384, nullptr, ""});
    ASSERT_TRUE(plan.error.empty()) << plan.error;
    ASSERT_EQ(plan.views.size(), 3u);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(plan.views[std::size_t(c)].layer, c);
        EXPECT_EQ(plan.views[std::size_t(c)].group, plan.views[0].group);
        EXPECT_EQ(viewName(plan.views[std::size_t(c)].view), "light 0 cascade:" + std::to_string(c));
    }
    EXPECT_EQ(plan.layers.at(plan.views[0].group), 3);
    // The camera moves: the planner's reason says the cascades follow it (tests/unit/test_shadow_planner.cpp).
    const ViewCamera moved = eyeCamera({40, 1.7, 0}, {0, 0, -1});  // beyond the far cascade's texel
    const ShadowPlan next =
        planShadowViews({scene, s, bounds.centreOrOrigin(), &moved, std::nullopt, city, 0, 16384, &plan, ""});
    for (const PlannedView& p : next.views) EXPECT_EQ(p.reason, "the camera moved (the cascade follows it)") << viewName(p.view);
    std::string error;
    EXPECT_TRUE(findView(plan.lightViews(0), "cascade:2", error)) << error;
    EXPECT_FALSE(findView(plan.lightViews(0), "cascade:3", error));
    EXPECT_NE(error.find("cascade:0, cascade:1, cascade:2"), std::string::npos) << error;
}

// HARD_CASES 18: a tiny camera near plane. The tight fit's practical splits start where the scene does, so its first
// cascade holds what the camera sees; the stable fit's splits depend only on the camera's planes and the keys.
TEST(Cascades, TightSplitsStartWhereTheSceneDoesStableOnesDoNotMove) {
    Bounds bounds;
    bounds.extend(glm::vec3(-5.0f, 0.0f, -5.0f));
    bounds.extend(glm::vec3(5.0f, 2.0f, 5.0f));
    ViewCamera camera = eyeCamera({0, 8, 25}, {0, -0.3, -1});
    camera.nearPlane = 0.004;
    camera.farPlane = 40.0;
    const ViewDepths range = boundsDepthRange(bounds, glm::dvec3(0.0), camera);
    EXPECT_GT(range.nearest, 15.0);
    LightSettings light = sun(3);
    light.projection.cascadeFit = CascadeFit::Tight;
    std::string error;
    const auto tight = buildLightViews(light, 0, bounds, glm::dvec3(0.0), &camera, error);
    ASSERT_TRUE(tight) << error;
    EXPECT_GT((*tight)[0].slice.farDepth, range.nearest);
    EXPECT_LE((*tight)[2].slice.farDepth, range.farthest + 1e-9);
    light.projection.cascadeFit = CascadeFit::Stable;
    const auto stable = buildLightViews(light, 0, bounds, glm::dvec3(0.0), &camera, error);
    ASSERT_TRUE(stable) << error;
    std::string why;
    EXPECT_EQ((*stable)[0].slice.farDepth, cascadeFarDepths(light.projection, camera, why)[0]);
    EXPECT_LT((*stable)[0].slice.farDepth, range.nearest);  // the stable fit's first cascade holds empty air here
}

// HARD_CASES 18: a near plane so small that f / n overflows (a glTF camera's znear may be any positive double). The
// practical splits stay finite and increasing (the logarithmic term starts at f x float's epsilon), and every
// cascade's matrix stays finite in float, as the GPU gets it, for both fits.
TEST(Cascades, PracticalSplitsStayFiniteWhenFarOverNearOverflows) {
    ViewCamera camera = eyeCamera({0, 1.7, 0}, {0, 0, -1});
    camera.nearPlane = 1e-307;
    camera.farPlane = 1e4;  // f / n = 1e311 > DBL_MAX
    ProjectionSettings p;
    p.cascadeCount = 4;
    p.splitLambda = 1.0f;
    std::string why;
    const std::vector<double> far = cascadeFarDepths(p, camera, why);
    ASSERT_EQ(far.size(), 4u) << why;
    double before = camera.nearPlane;
    for (std::size_t i = 0; i < far.size(); ++i) {
        ASSERT_TRUE(std::isfinite(far[i])) << "split " << i;
        EXPECT_GT(far[i], before) << "split " << i;
        before = far[i];
    }
    const double logNear = 1e4 * double(std::numeric_limits<float>::epsilon());
    EXPECT_NEAR(far[1], std::sqrt(logNear * 1e4), 1e-9);  // n' (f/n')^(1/2)
    for (CascadeFit fit : {CascadeFit::Stable, CascadeFit::Tight}) {
        LightSettings light = sun();
        light.projection.splitLambda = 1.0f;
        light.projection.cascadeFit = fit;
        std::string error;
        const Bounds bounds = cityBounds();
        const auto views = buildLightViews(light, 0, bounds, bounds.centreOrOrigin(), &camera, error);
        ASSERT_TRUE(views) << error;
        for (const ShadowView& v : *views) {
            const glm::mat4 gpu(v.space.viewProjection());
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(gpu[c][r])) << "fit " << int(fit) << " cascade " << v.index;
        }
    }
}

// A range a few ulps wide: the uniform splits round onto the near plane and onto each other. Zero-width slices are
// merged (fewer cascades), so the depths stay strictly increasing and end at the shadow distance.
TEST(Cascades, ZeroWidthSlicesAreMerged) {
    ViewCamera camera = eyeCamera({0, 1.7, 0}, {0, 0, -1});
    camera.nearPlane = 1.0;
    camera.farPlane = std::nextafter(std::nextafter(1.0, 2.0), 2.0);  // two ulps beyond the near plane
    ProjectionSettings p;
    p.cascadeCount = 4;
    p.splitLambda = 0.0f;
    std::string why;
    const std::vector<double> far = cascadeFarDepths(p, camera, why);
    ASSERT_FALSE(far.empty()) << why;
    EXPECT_LT(far.size(), 4u);
    double before = camera.nearPlane;
    for (double depth : far) {
        EXPECT_GT(depth, before);
        before = depth;
    }
    EXPECT_EQ(far.back(), camera.farPlane);
    LightSettings light = sun();
    light.projection.splitLambda = 0.0f;
    std::string error;
    const Bounds bounds = cityBounds();
    const auto views = buildLightViews(light, 0, bounds, bounds.centreOrOrigin(), &camera, error);
    ASSERT_TRUE(views) << error;
    EXPECT_EQ(views->size(), far.size());
}

// The tight fit tightens the splits to the depths the scene covers in reach; where that leaves no range (the scene
// beyond the shadow distance, or a flat scene facing the camera) it keeps the camera's range instead of collapsing
// every slice to zero width (which was refused, blaming projection.shadowDistance).
TEST(Cascades, TightFitKeepsTheCameraRangeWhenTheSceneLeavesNone) {
    const ViewCamera camera = eyeCamera({0, 1.7, 0}, {0, 0, -1});
    LightSettings light = sun();
    light.projection.cascadeFit = CascadeFit::Tight;
    light.projection.shadowDistance = 50.0f;
    Bounds far, flat;
    far.extend(glm::vec3(-10.0f, 0.0f, -300.0f));  // beyond the shadow distance
    far.extend(glm::vec3(10.0f, 5.0f, -200.0f));
    flat.extend(glm::vec3(-10.0f, -5.0f, -30.0f));  // a wall facing the camera: one depth
    flat.extend(glm::vec3(10.0f, 5.0f, -30.0f));
    for (const Bounds* bounds : {&far, &flat}) {
        std::string error;
        const auto views = buildLightViews(light, 0, *bounds, glm::dvec3(0.0), &camera, error);
        ASSERT_TRUE(views) << error;
        ASSERT_EQ(views->size(), 4u);
        EXPECT_EQ(views->back().slice.farDepth, 50.0);
        for (std::size_t i = 1; i < views->size(); ++i)
            EXPECT_GT((*views)[i].slice.farDepth, (*views)[i - 1].slice.farDepth);
    }
}
