// Shadow views, the one CPU view selection, and the planner (views/): no GL.
#include "settings/settings_fields.h"
#include "views/shadow_planner.h"
#include "views/view_select.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace shadowlab;

namespace {

Bounds box(glm::vec3 lo, glm::vec3 hi) {
    Bounds b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

LightSettings lightOf(LightType type) {
    LightSettings l;
    l.type = type;
    l.position = {1.0f, 6.0f, 2.0f};
    l.direction = {-0.3f, -1.0f, 0.2f};
    return l;
}

// A frame's plan with no previous one, for a scene of these bounds.
ShadowPlan planOf(const Settings& s, const Bounds& bounds, const glm::dvec3& origin,
                  const std::vector<CasterSphere>& casters = {}, int maxTextureSize = 16384,
                  const ShadowPlan* previous = nullptr) {
    Scene scene;
    scene.bounds = bounds;
    return planShadowViews({scene, s, origin, nullptr, std::nullopt, casters, 0, maxTextureSize, previous, ""});
}

// The texel-space position of p in a view: x, y in [-1, 1] inside its square, false behind it.
bool insideViewSquare(const LightSpace& space, const glm::dvec3& p) {
    const glm::dvec4 clip = space.viewProjection() * glm::dvec4(p, 1.0);
    if (!(clip.w > 0.0)) return false;
    return std::abs(clip.x / clip.w) <= 1.0 + 1e-9 && std::abs(clip.y / clip.w) <= 1.0 + 1e-9;
}

}  // namespace

TEST(ShadowViews, EachLightKindHasItsViews) {
    const Bounds bounds = box({-5, 0, -5}, {5, 3, 5});
    std::string error;
    for (LightType type : {LightType::Directional, LightType::Spot}) {
        const auto views = buildLightViews(lightOf(type), 3, bounds, bounds.centreOrOrigin(), nullptr, error);
        ASSERT_TRUE(views) << error;
        ASSERT_EQ(views->size(), 1u);
        EXPECT_EQ(views->front().kind, ShadowViewKind::Single);
        EXPECT_EQ(views->front().light, 3u);
        EXPECT_EQ(viewName(views->front()), "light 3");
    }
    const auto faces = buildLightViews(lightOf(LightType::Point), 2, bounds, bounds.centreOrOrigin(), nullptr, error);
    ASSERT_TRUE(faces) << error;
    ASSERT_EQ(faces->size(), 6u);
    for (int f = 0; f < 6; ++f) {
        EXPECT_EQ((*faces)[std::size_t(f)].kind, ShadowViewKind::CubeFace);
        EXPECT_EQ((*faces)[std::size_t(f)].cubeFace(), f);
    }
    EXPECT_EQ(viewName((*faces)[1]), "light 2 -X");
}

TEST(ShadowViews, ViewOptionNamesACubeFaceAndListsTheChoicesOtherwise) {
    const Bounds bounds = box({-5, 0, -5}, {5, 3, 5});
    std::string error;
    const auto faces = buildLightViews(lightOf(LightType::Point), 1, bounds, bounds.centreOrOrigin(), nullptr, error);
    ASSERT_TRUE(faces) << error;
    EXPECT_EQ(findView(*faces, "-Y", error), std::optional<std::size_t>(3));
    EXPECT_FALSE(findView(*faces, "up", error));
    EXPECT_NE(error.find("light 1 has no such view: it has 6 views (allowed: +X, -X, +Y, -Y, +Z, -Z)"), std::string::npos)
        << error;
    const auto spot = buildLightViews(lightOf(LightType::Spot), 0, bounds, bounds.centreOrOrigin(), nullptr, error);
    ASSERT_TRUE(spot) << error;
    EXPECT_FALSE(findView(*spot, "+X", error));
    EXPECT_NE(error.find("light 0 has one view"), std::string::npos) << error;
}

TEST(ShadowViews, AViewThatCannotBeFiniteNamesItsLight) {
    LightSettings l = lightOf(LightType::Spot);
    l.projection.autoFit = false;
    l.projection.nearPlane = 5.0f;
    l.projection.farPlane = 1.0f;
    std::string error;
    EXPECT_FALSE(buildLightViews(l, 4, box({-1, -1, -1}, {1, 1, 1}), glm::dvec3(0.0), nullptr, error));
    EXPECT_EQ(error.rfind("lights.4: ", 0), 0u) << error;
}

// The selection's definition: the view it picks holds the point inside its square. For a point light every
// direction is in exactly one face (away from the edges), and every face is picked.
TEST(ViewSelection, TheChosenCubeFaceHoldsThePoint) {
    const Bounds bounds = box({-5, 0, -5}, {5, 3, 5});
    std::string error;
    const auto faces = buildLightViews(lightOf(LightType::Point), 0, bounds, bounds.centreOrOrigin(), nullptr, error);
    ASSERT_TRUE(faces) << error;
    std::mt19937 rng(2026);
    std::uniform_real_distribution<double> coord(-20.0, 20.0);
    std::set<int> picked;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 p(coord(rng), coord(rng), coord(rng));
        const ShadowView* view = viewHolding(*faces, p);
        ASSERT_NE(view, nullptr);
        picked.insert(view->index);
        EXPECT_TRUE(insideViewSquare(view->space, p)) << "point " << p.x << "," << p.y << "," << p.z << " face "
                                                      << view->index;
        EXPECT_EQ(view->index, cubeFaceOf(p - view->space.position));
    }
    EXPECT_EQ(picked.size(), 6u);
}

TEST(ViewSelection, ASingleViewHoldsEveryPointAndNoViewHoldsNone) {
    const Bounds bounds = box({-5, 0, -5}, {5, 3, 5});
    std::string error;
    const auto views = buildLightViews(lightOf(LightType::Spot), 0, bounds, bounds.centreOrOrigin(), nullptr, error);
    ASSERT_TRUE(views) << error;
    EXPECT_EQ(selectView(*views, glm::dvec3(100.0, -50.0, 3.0)).view, 0);
    EXPECT_EQ(selectView({}, glm::dvec3(0.0)).view, -1);
}

TEST(ViewSelection, TiesGoToXThenYThenZAndZeroIsPositive) {
    EXPECT_EQ(cubeFaceOf({1.0, 1.0, 1.0}), 0);
    EXPECT_EQ(cubeFaceOf({-1.0, 1.0, 0.5}), 1);
    EXPECT_EQ(cubeFaceOf({0.5, -1.0, 1.0}), 3);
    EXPECT_EQ(cubeFaceOf({0.0, 0.0, -2.0}), 5);
    EXPECT_EQ(cubeFaceOf({0.0, 0.0, 0.0}), 0);
}

TEST(ShadowPlanner, GroupsViewsIntoArraysWithALayerEach) {
    Settings s;
    s.lights = {lightOf(LightType::Directional), lightOf(LightType::Point), lightOf(LightType::Spot),
                lightOf(LightType::Point), lightOf(LightType::Spot)};
    s.lights[2].shadow.resolution = 512;  // its own 2D array
    s.lights[4].enabled = false;
    const Bounds bounds = box({-5, 0, -5}, {5, 3, 5});
    const ShadowPlan plan = planOf(s, bounds, bounds.centreOrOrigin());
    ASSERT_TRUE(plan.error.empty()) << plan.error;
    ASSERT_EQ(plan.views.size(), 1u + 6u + 1u + 6u);
    ASSERT_EQ(plan.lightsWithoutViews.size(), 1u);
    EXPECT_EQ(plan.lightsWithoutViews[0].light, 4u);
    EXPECT_NE(plan.lightsWithoutViews[0].reason.find("enabled false"), std::string::npos);
    ASSERT_EQ(plan.layers.size(), 3u);  // 2D at the default size, 2D at 512, one cube array
    std::map<MapGroup, std::set<int>> used;
    for (const PlannedView& p : plan.views) {
        EXPECT_TRUE(used[p.group].insert(p.layer).second) << "layer " << p.layer << " used twice";
        EXPECT_EQ(p.group.cube, p.view.kind == ShadowViewKind::CubeFace);
        EXPECT_EQ(p.group.resolution, s.lights[p.view.light].shadow.resolution);
    }
    for (const auto& [group, layers] : plan.layers) EXPECT_EQ(int(used[group].size()), layers);
    EXPECT_EQ(plan.lightViews(1).size(), 6u);
    EXPECT_EQ(plan.lightViews(4).size(), 0u);
}

TEST(ShadowPlanner, ARefusedResolutionKeepsTheLightsMapOrStopsTheFrame) {
    Settings s;
    s.lights = {lightOf(LightType::Spot)};
    s.lights[0].shadow.resolution = 8192;
    const Bounds bounds = box({-5, 0, -5}, {5, 3, 5});
    const ShadowPlan none = planOf(s, bounds, glm::dvec3(0.0), {}, 4096);
    EXPECT_NE(none.error.find("shadow.resolution: 8192"), std::string::npos) << none.error;
    // The previous frame's plan gave the light a 1024² d24 map: the refused size keeps it.
    Settings before = s;
    before.lights[0].shadow.resolution = 1024;
    before.lights[0].shadow.format = DepthFormat::D24;
    const ShadowPlan previous = planOf(before, bounds, glm::dvec3(0.0), {}, 4096);
    ASSERT_TRUE(previous.error.empty()) << previous.error;
    const ShadowPlan kept = planOf(s, bounds, glm::dvec3(0.0), {}, 4096, &previous);
    ASSERT_TRUE(kept.error.empty()) << kept.error;
    ASSERT_EQ(kept.warnings.size(), 1u);
    EXPECT_NE(kept.warnings[0].find("keeping the 1024² map"), std::string::npos) << kept.warnings[0];
    EXPECT_EQ(kept.settings.lights[0].shadow.resolution, 1024);
    EXPECT_EQ(kept.views.front().group.format, DepthFormat::D24);
}

TEST(ShadowPlanner, ClearsTheViewsWithNoCasterInTheirVolume) {
    Settings s;
    s.lights = {lightOf(LightType::Point)};
    const Bounds bounds = box({-5, 0, -5}, {5, 3, 5});
    const glm::dvec3 origin = bounds.centreOrOrigin();
    const glm::dvec3 light = glm::dvec3(s.lights[0].position) - origin;
    // One small caster straight below the light: only the -Y face holds it.
    const std::vector<CasterSphere> casters = {{light + glm::dvec3(0.0, -4.0, 0.0), 0.5, true}};
    const ShadowPlan plan = planOf(s, bounds, origin, casters);
    ASSERT_EQ(plan.views.size(), 6u);
    for (const PlannedView& p : plan.views)
        EXPECT_EQ(p.action, p.view.index == 3 ? ViewAction::Render : ViewAction::Clear) << viewName(p.view);
}

