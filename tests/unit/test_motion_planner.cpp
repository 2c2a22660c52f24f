// The planner with moving casters (views/caster_motion.h): a motion dirties only the views whose volume held the
// caster before or holds it now; a frame where nothing moved renders nothing; a cachedStatic light redraws a moved
// dynamic caster over its cached static depth within the rectangle it covers; each light's update policy decides
// when. Pure: spheres and poses in, actions and reasons out.
#include "views/shadow_planner.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace shadowlab;

namespace {

// A point light at the origin (six faces) and casters around it: a car on +X (dynamic) and static blocks on +X, -X,
// +Z and below. Every sphere is small enough to sit in one face only.
struct Street {
    Scene scene;
    Settings settings;
    std::vector<CasterSphere> casters{{{5.0, 0.0, 0.0}, 0.5, true},    // 0: the car
                                      {{6.0, 0.0, 3.0}, 0.5, true},    // 1: a block on +X
                                      {{6.0, 0.0, -3.0}, 0.5, true},   // 2: another on +X
                                      {{-5.0, 0.0, 0.0}, 0.5, true},   // 3: on -X
                                      {{0.0, 0.0, 5.0}, 0.5, true},    // 4: on +Z
                                      {{0.0, -5.0, 0.0}, 0.5, true},   // 5: below
                                      {{0.0, 5.0, 0.0}, 0.5, true},    // 6: above
                                      {{0.0, 0.0, -5.0}, 0.5, true}};  // 7: on -Z
    std::vector<char> statics{0, 1, 1, 1, 1, 1, 1, 1};

    Street() {
        scene.bounds.extend(glm::vec3(-10.0f));
        scene.bounds.extend(glm::vec3(10.0f));
        LightSettings lamp;
        lamp.type = LightType::Point;
        lamp.position = {0.0f, 0.0f, 0.0f};
        lamp.range = 20.0f;
        settings.lights = {lamp};
    }

    ShadowPlan plan(const Settings& s, const ShadowPlan* previous, const CasterMotion* motion,
                    std::uint64_t frame = 0) const {
        return planShadowViews({scene, s, glm::dvec3(0.0), nullptr, std::nullopt, casters, 42, 16384, previous, "",
                                motion, &statics, frame});
    }
    // The car from `from` to `to`, as the Renderer reports it.
    CasterMotion drive(std::uint64_t pose, glm::dvec3 from, glm::dvec3 to) {
        casters[0].center = to;
        return {pose, {{0, "Traffic/car 3", {from, 0.5, true}, {to, 0.5, true}}}};
    }
};

const PlannedView& face(const ShadowPlan& plan, int f) {
    for (const PlannedView& p : plan.views)
        if (p.view.cubeFace() == f) return p;
    throw std::runtime_error("no face " + std::to_string(f));
}

constexpr int kPosX = 0, kNegX = 1, kPosZ = 4;

}  // namespace

TEST(MotionPlanner, OneMovingCasterDirtiesOnlyTheViewsItWasOrIsIn) {
    Street s;
    const CasterMotion still{};
    const ShadowPlan first = s.plan(s.settings, nullptr, &still);
    ASSERT_TRUE(first.error.empty()) << first.error;
    ASSERT_EQ(first.views.size(), 6u);
    // +X to +Z: the two faces it left and entered render, the other four are reused.
    const CasterMotion motion = s.drive(1, {5.0, 0.0, 0.0}, {0.5, 0.0, 5.5});
    const ShadowPlan next = s.plan(s.settings, &first, &motion);
    EXPECT_EQ(viewsToRender(next), 2);
    for (const PlannedView& p : next.views) {
        const bool touched = p.view.cubeFace() == kPosX || p.view.cubeFace() == kPosZ;
        EXPECT_EQ(p.action, touched ? ViewAction::Render : ViewAction::Keep) << viewName(p.view) << ": " << p.reason;
        EXPECT_EQ(describeUpdate(p), touched ? "full: Traffic/car 3 moved"
                                             : "reused: unchanged: nothing that moved is in its volume")
            << viewName(p.view);
        ASSERT_TRUE(p.holds);
        EXPECT_EQ(p.holds->pose, 1u) << viewName(p.view);  // every map now holds the new pose
    }
    // The next frame with no motion: nothing renders.
    const CasterMotion stillThen{1, {}};
    EXPECT_EQ(viewsToRender(s.plan(s.settings, &next, &stillThen)), 0);
}

TEST(MotionPlanner, NothingMovedRendersNoViewWhateverThePolicyButEveryFrame) {
    Street s;
    const CasterMotion still{};
    for (ShadowUpdate policy : {ShadowUpdate::OnChange, ShadowUpdate::CachedStatic, ShadowUpdate::EveryNthFrame}) {
        Settings settings = s.settings;
        settings.lights[0].shadow.update = policy;
        const ShadowPlan first = s.plan(settings, nullptr, &still);
        EXPECT_EQ(viewsToRender(first), 6);
        EXPECT_EQ(viewsToRender(s.plan(settings, &first, &still, 4)), 0) << int(policy);
    }
    Settings every = s.settings;
    every.lights[0].shadow.update = ShadowUpdate::EveryFrame;
    const ShadowPlan first = s.plan(every, nullptr, &still);
    const ShadowPlan next = s.plan(every, &first, &still);
    EXPECT_EQ(viewsToRender(next), 6);
    EXPECT_EQ(describeUpdate(face(next, kNegX)), "full: shadow.update everyFrame");
}

TEST(MotionPlanner, ALightChangeIsAFullRenderThatRebuildsTheStaticCache) {
    Street s;
    s.settings.lights[0].shadow.update = ShadowUpdate::CachedStatic;
    const CasterMotion still{};
    const ShadowPlan first = s.plan(s.settings, nullptr, &still);
    Settings moved = s.settings;
    moved.lights[0].position = {0.5f, 0.0f, 0.0f};
    const CasterMotion motion = s.drive(1, {5.0, 0.0, 0.0}, {5.0, 0.0, 0.5});
    const ShadowPlan next = s.plan(moved, &first, &motion);
    EXPECT_EQ(viewsToRender(next), 6);
    for (const PlannedView& p : next.views) {
        EXPECT_EQ(p.cache, CacheState::Full) << viewName(p.view);
        EXPECT_TRUE(p.fromStaticCache) << viewName(p.view);  // its static casters go into the cached depth again
        EXPECT_EQ(describeUpdate(p), "full: position changed") << viewName(p.view);
        ASSERT_TRUE(p.holds);
        EXPECT_TRUE(p.holds->staticCache);
    }
}

TEST(MotionPlanner, ACachedViewRedrawsOnlyTheMovedDynamicCasterWithinItsRectangle) {
    Street s;
    s.settings.lights[0].shadow.update = ShadowUpdate::CachedStatic;
    const CasterMotion still{};
    const ShadowPlan first = s.plan(s.settings, nullptr, &still);
    const CasterMotion motion = s.drive(1, {5.0, 0.0, 0.0}, {5.0, 0.4, 0.3});
    const ShadowPlan next = s.plan(s.settings, &first, &motion);
    EXPECT_EQ(viewsToRender(next), 1);
    const PlannedView& p = face(next, kPosX);
    EXPECT_EQ(describeUpdate(p), "static + dynamic: Traffic/car 3 moved");
    EXPECT_EQ(p.dynamicCasters, std::vector<std::size_t>{0});  // the blocks on +X stay in the cached depth
    // The rectangle holds the car's old and new projections, and is a small part of the 2048² face.
    const TexelRect before = casterTexels(motion.moved[0].before, p.view.space);
    const TexelRect after = casterTexels(motion.moved[0].after, p.view.space);
    TexelRect both = before;
    both.extend(after);
    EXPECT_EQ(p.rect, both);
    EXPECT_FALSE(before == after);
    EXPECT_LT(p.rect.area(), 2048LL * 2048 / 10);
    EXPECT_FALSE(p.rect.overlaps(casterTexels(s.casters[1], p.view.space)));
    ASSERT_TRUE(p.holds);
    EXPECT_TRUE(p.holds->staticCache);
}

TEST(MotionPlanner, ACachedViewWithNoStaticCasterInItsVolumeRedrawsInFull) {
    Street s;
    s.settings.lights[0].shadow.update = ShadowUpdate::CachedStatic;
    s.statics = {0, 0, 0, 1, 1, 1, 1, 1};  // the blocks on +X are dynamic too: the +X face's cached depth is empty
    const CasterMotion still{};
    const ShadowPlan first = s.plan(s.settings, nullptr, &still);
    const CasterMotion motion = s.drive(1, {5.0, 0.0, 0.0}, {5.0, 0.4, 0.3});
    const ShadowPlan next = s.plan(s.settings, &first, &motion);
    const PlannedView& p = face(next, kPosX);
    EXPECT_EQ(p.action, ViewAction::Render);
    EXPECT_EQ(describeUpdate(p), "full: Traffic/car 3 moved (no static caster in its volume: its cached depth is empty)");
    EXPECT_TRUE(p.fromStaticCache);  // drawn through its (empty) cached depth, which stays valid
}

TEST(MotionPlanner, AStaticFlaggedCasterThatMovesIsLeftInTheCacheWithAWarningNamingIt) {
    Street s;
    s.settings.lights[0].shadow.update = ShadowUpdate::CachedStatic;
    s.statics[0] = 1;  // casters.static lists the car
    const CasterMotion still{};
    const ShadowPlan first = s.plan(s.settings, nullptr, &still);
    const CasterMotion motion = s.drive(1, {5.0, 0.0, 0.0}, {5.0, 0.0, 0.5});
    const ShadowPlan next = s.plan(s.settings, &first, &motion);
    EXPECT_EQ(viewsToRender(next), 0);
    EXPECT_EQ(face(next, kPosX).cache, CacheState::Reused);
    ASSERT_EQ(next.warnings.size(), 1u);
    EXPECT_NE(next.warnings[0].find("casters.static: Traffic/car 3 moved"), std::string::npos) << next.warnings[0];
    // The same motion under onChange renders the face (the static flag only matters to a cache).
    Settings onChange = s.settings;
    onChange.lights[0].shadow.update = ShadowUpdate::OnChange;
    const ShadowPlan firstOnChange = s.plan(onChange, nullptr, &still);
    EXPECT_EQ(face(s.plan(onChange, &firstOnChange, &motion), kPosX).action, ViewAction::Render);
}

TEST(MotionPlanner, EveryNthFrameLetsMotionWaitForItsFrame) {
    Street s;
    s.settings.lights[0].shadow.update = ShadowUpdate::EveryNthFrame;
    s.settings.lights[0].shadow.updateInterval = 3;
    const CasterMotion still{};
    const ShadowPlan first = s.plan(s.settings, nullptr, &still, 0);
    const CasterMotion motion = s.drive(1, {5.0, 0.0, 0.0}, {5.0, 0.0, 0.5});
    const ShadowPlan waits = s.plan(s.settings, &first, &motion, 1);
    EXPECT_EQ(viewsToRender(waits), 0);
    EXPECT_NE(face(waits, kPosX).reason.find("waits 2 frame(s)"), std::string::npos) << face(waits, kPosX).reason;
    const CasterMotion stillAfter{1, {}};
    EXPECT_EQ(viewsToRender(s.plan(s.settings, &waits, &stillAfter, 2)), 0);
    // Frame 3: the face that missed the motion draws; the others were posed along.
    const ShadowPlan due = s.plan(s.settings, &waits, &stillAfter, 3);
    EXPECT_EQ(viewsToRender(due), 1);
    EXPECT_EQ(describeUpdate(face(due, kPosX)), "full: casters moved while it was not drawn");
}

TEST(MotionPlanner, CasterTexelsHoldTheSphereAndTheWholeMapWhenUnbounded) {
    LightSpace ortho;
    ortho.projection = glm::dmat4(1.0);  // clip = view: the map spans [-1, 1]
    ortho.resolution = 100;
    const TexelRect r = casterTexels({{0.0, 0.0, -0.5}, 0.125, true}, ortho);
    EXPECT_EQ(r, (TexelRect{42, 42, 58, 58}));  // [43.75, 56.25] to whole texels, widened by one
    EXPECT_EQ(casterTexels({{0.0, 0.0, 0.0}, 0.1, false}, ortho), (TexelRect{0, 0, 100, 100}));
    EXPECT_TRUE(casterTexels({{5.0, 0.0, 0.0}, 0.1, true}, ortho).empty());
}
