// The planner as a pure function of (scene, settings, camera, the previous plan): which views a frame renders and
// why, with no GL. The reasons come from the key table's shadow-view tags.
#include "key_values.h"
#include "settings/settings_fields.h"
#include "views/shadow_planner.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using namespace shadowlab;

namespace {

// A 100 x 100 street block: a cascaded sun, a spot light and a point light, one caster as large as the block (in
// every view's volume), and a camera at eye height.
struct World {
    Scene scene;
    Settings settings;
    std::vector<CasterSphere> casters;
    glm::dvec3 origin{0.0, 10.0, 0.0};

    World() {
        scene.bounds.extend(glm::vec3(-50.0f, 0.0f, -50.0f));
        scene.bounds.extend(glm::vec3(50.0f, 20.0f, 50.0f));
        SceneLight lamp;  // the file's own light (useSceneLights)
        lamp.type = SceneLightType::Point;
        lamp.position = {0.0f, 10.0f, 0.0f};
        scene.lights = {lamp};
        LightSettings sun;
        sun.type = LightType::Directional;
        sun.direction = {-0.3f, -1.0f, 0.2f};
        sun.projection.fit = ProjectionFit::Cascades;
        sun.projection.cascadeCount = 3;
        LightSettings spot;
        spot.type = LightType::Spot;
        spot.position = {10.0f, 15.0f, 10.0f};
        spot.direction = {0.0f, -1.0f, 0.1f};
        LightSettings point;
        point.type = LightType::Point;
        point.position = {-10.0f, 8.0f, -10.0f};
        settings.lights = {sun, spot, point};
        casters = {{glm::dvec3(0.0), 80.0, true}};
    }

    ViewCamera camera(glm::dvec3 eye = {0.0, 1.7, 30.0}) const {
        ViewCamera c;
        c.eye = eye - origin;
        c.forward = {0.0, 0.0, -1.0};
        c.right = {1.0, 0.0, 0.0};
        c.up = {0.0, 1.0, 0.0};
        c.aspect = 16.0 / 9.0;
        c.nearPlane = 0.1;
        c.farPlane = 150.0;
        return c;
    }

    ShadowPlan plan(const Settings& s, const ViewCamera& c, const ShadowPlan* previous,
                    std::optional<glm::dmat4> cameraViewProjection = std::nullopt) const {
        return planShadowViews({scene, s, origin, &c, cameraViewProjection, casters, 42, 16384, previous, ""});
    }
    ShadowPlan plan(const Settings& s, const ShadowPlan* previous) const { return plan(s, camera(), previous); }
};

const PlannedView& viewOf(const ShadowPlan& plan, std::size_t light) {
    for (const PlannedView& p : plan.views)
        if (p.view.light == light) return p;
    throw std::runtime_error("light " + std::to_string(light) + " has no view");
}

}  // namespace

TEST(ShadowPlanner, AnUnchangedFrameRendersNothing) {
    const World w;
    const ShadowPlan first = w.plan(w.settings, nullptr);
    ASSERT_TRUE(first.error.empty()) << first.error;
    ASSERT_EQ(first.views.size(), 3u + 1u + 6u);
    for (const PlannedView& p : first.views) {
        EXPECT_EQ(p.action, ViewAction::Render) << viewName(p.view);
        EXPECT_EQ(p.reason, "first frame");
    }
    const ShadowPlan second = w.plan(w.settings, &first);
    EXPECT_EQ(viewsToRender(second), 0);
    for (const PlannedView& p : second.views) {
        EXPECT_EQ(p.action, ViewAction::Keep) << viewName(p.view) << ": " << p.reason;
        EXPECT_TRUE(p.holds) << viewName(p.view);
    }
    // Still nothing on the third frame: what the maps hold is carried from plan to plan.
    EXPECT_EQ(viewsToRender(w.plan(w.settings, &second)), 0);
}

TEST(ShadowPlanner, ACameraMoveRerendersTheCascadesButNotTheSpotOrPointLight) {
    const World w;
    const ShadowPlan first = w.plan(w.settings, nullptr);
    const ShadowPlan moved = w.plan(w.settings, w.camera({4.0, 1.7, 25.0}), &first);
    ASSERT_TRUE(moved.error.empty()) << moved.error;
    for (const PlannedView& p : moved.views) {
        if (p.view.kind == ShadowViewKind::Cascade) {
            EXPECT_EQ(p.action, ViewAction::Render) << viewName(p.view);
            EXPECT_EQ(p.reason, "the camera moved (the cascade follows it)");
        } else {
            EXPECT_EQ(p.action, ViewAction::Keep) << viewName(p.view) << ": " << p.reason;
        }
    }
    EXPECT_EQ(viewsToRender(moved), 3);
}

// projection.depthBounds: when the seen depths move, the cascades re-render and the plan says that is why (a camera
// move with the same bounds says the camera moved).
TEST(ShadowPlanner, MovedDepthBoundsAreNamedAsTheCascadesReason) {
    const World w;
    Settings s = w.settings;
    s.lights[0].projection.depthBounds = DepthBounds::PreviousFrame;
    ViewCamera seen = w.camera();
    seen.seenDepths = ViewDepths{4.0, 32.0};
    const ShadowPlan first = w.plan(s, seen, nullptr);
    ASSERT_TRUE(first.error.empty()) << first.error;
    ViewCamera farther = seen;
    farther.seenDepths = ViewDepths{4.0, 90.0};
    const ShadowPlan bounds = w.plan(s, farther, &first);
    ViewCamera moved = w.camera({4.0, 1.7, 25.0});
    moved.seenDepths = seen.seenDepths;
    const ShadowPlan camera = w.plan(s, moved, &first);
    int cascades = 0;
    for (const ShadowPlan* plan : {&bounds, &camera})
        for (const PlannedView& p : plan->views) {
            if (p.view.kind != ShadowViewKind::Cascade) continue;
            ++cascades;
            EXPECT_EQ(p.action, ViewAction::Render) << viewName(p.view);
            EXPECT_EQ(p.reason, plan == &bounds ? "the depth bounds moved" : "the camera moved (the cascade follows it)")
                << viewName(p.view);
        }
    EXPECT_EQ(cascades, 6);
}

TEST(ShadowPlanner, AKeyChangeNamesTheKeyAndRerendersOnlyItsLight) {
    const World w;
    const ShadowPlan first = w.plan(w.settings, nullptr);
    Settings biased = w.settings;
    biased.lights[1].shadow.depthBias += 2.0f;
    const ShadowPlan next = w.plan(biased, &first);
    EXPECT_EQ(viewOf(next, 1).action, ViewAction::Render);
    EXPECT_EQ(viewOf(next, 1).reason, "shadow.depthBias changed");
    EXPECT_EQ(viewsToRender(next), 1);
    Settings coloured = w.settings;
    coloured.lights[1].color = {1.0f, 0.0f, 0.0f};  // shades the picture, not the map
    EXPECT_EQ(viewsToRender(w.plan(coloured, &first)), 0);
}

TEST(ShadowPlanner, AViewSkippedWhileUnseenRendersOnceSeenWithTheKeyThatChanged) {
    const World w;
    const ShadowPlan first = w.plan(w.settings, nullptr);
    Settings biased = w.settings;
    biased.lights[1].shadow.depthBias += 2.0f;
    // A camera far from every light's volume: the changed view waits.
    const glm::dmat4 away = glm::ortho(-1.0, 1.0, -1.0, 1.0, 0.1, 1.0) *
                            glm::lookAt(glm::dvec3(1e5), glm::dvec3(2e5), glm::dvec3(0.0, 1.0, 0.0));
    const ShadowPlan unseen = w.plan(biased, w.camera(), &first, away);
    EXPECT_EQ(viewOf(unseen, 1).action, ViewAction::SkipUnseen) << viewOf(unseen, 1).reason;
    EXPECT_EQ(viewsToRender(unseen), 0);
    // Seen again with the same settings: its map still holds the old bias, so it renders and says why.
    const ShadowPlan seen = w.plan(biased, &unseen);
    EXPECT_EQ(viewOf(seen, 1).action, ViewAction::Render);
    EXPECT_EQ(viewOf(seen, 1).reason, "shadow.depthBias changed");
    EXPECT_EQ(viewsToRender(seen), 1);
}

TEST(ShadowPlanner, AnArrayThatGrowsRerendersTheViewsItHeld) {
    const World w;
    const ShadowPlan first = w.plan(w.settings, nullptr);
    Settings more = w.settings;
    more.lights.push_back(w.settings.lights[1]);  // a second spot: the 2D array gains a layer, the cube array not
    const ShadowPlan next = w.plan(more, &first);
    for (const PlannedView& p : next.views) {
        const std::string expected = p.view.light == 3                             ? "new view"
                                     : p.view.kind == ShadowViewKind::CubeFace ? "unchanged: light, casters and shadow settings are the same"
                                                                               : "shadow map reallocated";
        EXPECT_EQ(p.reason, expected) << viewName(p.view);
    }
}

// The key table drives the reasons: every key tagged as changing shadow views, changed to any value it accepts,
// re-renders a view whose reason names it (or leaves its light without a view, saying so by the key); a key without
// the tag re-renders nothing. A new key tagged without the planner seeing it fails here.
TEST(ShadowPlanner, EveryKeyTaggedForShadowViewsNamesItselfAndNoOtherKeyRerenders) {
    const World w;
    const ShadowPlan first = w.plan(w.settings, nullptr);
    ASSERT_TRUE(first.error.empty()) << first.error;
    int taggedChecked = 0, untaggedChecked = 0;
    for (const SettingsField* field : settingsFieldsOf(w.settings)) {
        const bool tagged = field->invalidates & kInvalidatesShadowView;
        const std::string name = field->light >= 0 ? std::string(field->lightKey()) : field->key;
        int values = 0;
        for (const nlohmann::json& value : test::otherValues(*field, field->get(w.settings))) {
            Settings changed = w.settings;
            if (!field->set(changed, value).empty() || !changed.validate().empty()) continue;
            const ShadowPlan next = w.plan(changed, &first);
            if (!next.error.empty() || !next.warnings.empty()) continue;  // e.g. a size the GPU refuses: kept map
            ++values;
            const std::string what = field->key + "=" + value.dump();
            if (!tagged) {
                EXPECT_EQ(viewsToRender(next), 0) << what << " re-rendered a view: " << next.views.front().reason;
                continue;
            }
            bool named = false;
            for (const PlannedView& p : next.views) {
                if (field->light >= 0 && p.view.light != std::size_t(field->light)) continue;
                // Rendered, or cleared where the change left no caster in its volume.
                EXPECT_TRUE(p.action == ViewAction::Render || p.action == ViewAction::Clear)
                    << what << ": " << viewName(p.view) << ": " << p.reason;
                named = named || p.reason.find(name) != std::string::npos;
            }
            for (const LightWithoutView& l : next.lightsWithoutViews)
                if (field->light < 0 || l.light == std::size_t(field->light))
                    named = named || l.reason.find(name) != std::string::npos;
            EXPECT_TRUE(named) << what << ": no reason names " << name;
        }
        EXPECT_GT(values, 0) << field->key << ": no value to try";
        (tagged ? taggedChecked : untaggedChecked) += values > 0;
    }
    EXPECT_GT(taggedChecked, 25);
    EXPECT_GT(untaggedChecked, 15);
}
