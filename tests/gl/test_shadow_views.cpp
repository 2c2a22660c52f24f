// Issue 10: every light casts. Point lights cast through six cube faces; several lights add up, each shadowed by
// its own map; the planner renders only the views that changed and skips those that cannot change the picture.
#include "gl_fixture.h"

#include "scene/builtin_scenes.h"
#include "settings/settings_fields.h"

#include <algorithm>

namespace shadowlab::test {
namespace {

class ShadowViews : public GlTest {};

void set(Settings& s, const char* keyValue) { ASSERT_EQ(applySettingOverride(s, keyValue), "") << keyValue; }

int viewsThatRan(const FrameStats& stats) {
    return int(std::count_if(stats.views.begin(), stats.views.end(), [](const ShadowViewStats& v) { return v.ran; }));
}

TEST_F(ShadowViews, APointLightsShadowFallsWhereItsRaysSayOnEveryFace) {
    // Light at (3, 4, 0); the textbook cube spans x, z in [-1, 1], y in [0, 2]. The ray to floor point (-2.6, 0, 0)
    // passes (-0.5, 1.5, 0), inside the cube: shadowed. (5, 0, 0), (0, 0, 6) and (-2.6, 0, 2.5) see the light.
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = topDownShadowView(loadShippedPreset("default"));
    set(s, "lights.0.type=point");
    set(s, "lights.0.position=3,4,0");
    const View view = renderView(renderer, scene, s);
    saveView(view, "point-light-textbook");
    ASSERT_EQ(view.stats.views.size(), 6u);
    for (int face = 0; face < 6; ++face) EXPECT_EQ(view.stats.views[std::size_t(face)].face, face);
    EXPECT_LT(view.meanRedAround({-2.6, 0.0, 0.0}, 2), 40.0);
    EXPECT_GT(view.meanRedAround({5.0, 0.0, 0.0}, 2), 215.0);
    EXPECT_GT(view.meanRedAround({0.0, 0.0, 6.0}, 2), 215.0);
    EXPECT_GT(view.meanRedAround({-2.6, 0.0, 2.5}, 2), 215.0);
    // Behind the light's other side (+x): the floating box at (4, 3, -3) shadows the floor toward +x, -z from it.
    EXPECT_GT(view.meanRedAround({8.0, 0.0, 8.0}, 2), 215.0);
}

TEST_F(ShadowViews, CubeSeamsShowNoAcneOnAnOpenFloor) {
    // A point light 2.5 over the floor: the floor crosses the -Y face and four side faces; between z = 4.5 and 9.5
    // nothing casts, so every floor pixel there must be lit, on the seams too (HARD_CASES 9).
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = topDownShadowView(loadShippedPreset("default"));
    set(s, "lights.0.type=point");
    set(s, "lights.0.position=0.3,2.5,7");
    const View view = renderView(renderer, scene, s, 480, 480);
    saveView(view, "point-light-seams");
    int checked = 0, dark = 0;
    for (double x = -9.0; x <= 9.0; x += 0.25)
        for (double z = 4.6; z <= 9.4; z += 0.25) {
            const int red = view.redAt({x, 0.0, z});
            if (red < 0) continue;
            ++checked;
            dark += red < 250;
        }
    EXPECT_GT(checked, 1000);
    EXPECT_EQ(dark, 0) << "of " << checked << " floor points, some near a cube seam are shadowed";
}

TEST_F(ShadowViews, APixelShadowedByOneLightKeepsTheOthersLight) {
    // (-1.4, 0, -1.2) lies in the cube's shadow from the default directional light; a point light at (-4, 3, -4)
    // sees it. (6, 0, 6) is lit by both.
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings one = topDownShadowView(loadShippedPreset("default"));
    one.view = ViewMode::Lit;
    Settings two = one;
    set(two, "lights.1.type=point");
    set(two, "lights.1.position=-4,3,-4");
    const View directionalOnly = renderView(renderer, scene, one);
    const View both = renderView(renderer, scene, two);
    saveView(both, "two-lights-lit");
    const glm::dvec3 shadowedByOne{-1.4, 0.0, -1.2}, litByBoth{6.0, 0.0, 6.0};
    EXPECT_GT(both.meanRedAround(shadowedByOne, 1), directionalOnly.meanRedAround(shadowedByOne, 1) + 20.0)
        << "the point light's contribution is missing where the directional light is blocked";
    EXPECT_LT(both.meanRedAround(shadowedByOne, 1), both.meanRedAround(litByBoth, 1));
    // Each light's shadow view: only the directional light's shadow there, the point light's elsewhere.
    Settings pointOff = two;
    set(pointOff, "lights.1.castsShadows=false");
    const View pointUnshadowed = renderView(renderer, scene, pointOff);
    EXPECT_NEAR(pointUnshadowed.meanRedAround(shadowedByOne, 1), both.meanRedAround(shadowedByOne, 1), 2.0);
    const auto castless = std::find_if(pointUnshadowed.stats.views.begin(), pointUnshadowed.stats.views.end(),
                                       [](const ShadowViewStats& v) { return v.light == 1; });
    ASSERT_NE(castless, pointUnshadowed.stats.views.end());
    EXPECT_FALSE(castless->hasView);
    EXPECT_NE(castless->reason.find("castsShadows is off"), std::string::npos) << castless->reason;
}

TEST_F(ShadowViews, AnUnchangedFrameRendersNoViewAndMovingOneLightRendersOnlyItsViews) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = loadShippedPreset("default");
    set(s, "lights.1.type=spot");
    set(s, "lights.1.position=-3,8,2");
    set(s, "lights.1.direction=0.3,-1,-0.2");
    set(s, "lights.2.type=point");
    set(s, "lights.2.position=2,3,4");
    const View first = renderView(renderer, scene, s);
    EXPECT_EQ(viewsThatRan(first.stats), 8);  // 1 + 1 + 6
    const View second = renderView(renderer, scene, s);
    EXPECT_EQ(viewsThatRan(second.stats), 0);
    EXPECT_FALSE(second.stats.shadowPass.ran);
    for (const ShadowViewStats& v : second.stats.views) EXPECT_EQ(v.reason.rfind("unchanged", 0), 0u) << v.reason;
    EXPECT_EQ(first.rgba, second.rgba);

    set(s, "lights.1.position=-3,8,2.5");
    const View moved = renderView(renderer, scene, s);
    EXPECT_EQ(viewsThatRan(moved.stats), 1);
    for (const ShadowViewStats& v : moved.stats.views) {
        if (v.light == 1) {
            EXPECT_TRUE(v.ran);
            EXPECT_EQ(v.reason, "position changed");
        } else {
            EXPECT_FALSE(v.ran) << v.name << ": " << v.reason;
        }
    }
    // A bias edit of the point light re-renders its six faces and nothing else.
    set(s, "lights.2.shadow.depthBias=3");
    const View biased = renderView(renderer, scene, s);
    EXPECT_EQ(viewsThatRan(biased.stats), 6);
    // Colour and intensity change the picture, not the maps.
    set(s, "lights.2.intensity=0.5");
    set(s, "lights.0.color=1,0.8,0.8");
    const View recoloured = renderView(renderer, scene, s);
    EXPECT_EQ(viewsThatRan(recoloured.stats), 0);
    EXPECT_NE(recoloured.rgba, biased.rgba);
}

TEST_F(ShadowViews, ALightWhoseVolumeMissesTheCameraRendersNoView) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = topDownShadowView(loadShippedPreset("default"));
    // A spot light far outside the view, pointing away from the scene.
    set(s, "lights.1.type=spot");
    set(s, "lights.1.position=60,5,60");
    set(s, "lights.1.direction=1,-0.1,1");
    set(s, "lights.1.projection.autoFit=false");
    set(s, "lights.1.projection.near=0.5");
    set(s, "lights.1.projection.far=30");
    const View view = renderView(renderer, scene, s);
    const auto spot = std::find_if(view.stats.views.begin(), view.stats.views.end(),
                                   [](const ShadowViewStats& v) { return v.light == 1; });
    ASSERT_NE(spot, view.stats.views.end());
    EXPECT_FALSE(spot->ran);
    EXPECT_EQ(spot->reason, "skipped: its volume misses the camera's view");
    // The directional light's view still rendered.
    EXPECT_TRUE(view.stats.views.front().ran);
}

TEST_F(ShadowViews, ShipsAsManyMapsAsViewsInArraysPerSizeAndFormat) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = loadShippedPreset("default");
    set(s, "lights.0.shadow.resolution=512");
    set(s, "lights.1.shadow.resolution=512");
    set(s, "lights.1.direction=0.4,-1,0.3");
    set(s, "lights.2.type=point");
    set(s, "lights.2.position=2,3,4");
    set(s, "lights.2.shadow.resolution=256");
    set(s, "lights.2.shadow.depthFormat=d16");
    const View view = renderView(renderer, scene, s);
    EXPECT_EQ(view.stats.shadowMapBytes, std::size_t(512) * 512 * 4 * 2 + std::size_t(256) * 256 * 2 * 6);
    EXPECT_EQ(view.stats.views.size(), 8u);
    ASSERT_NE(renderer.viewMap(2, 3), nullptr);
    EXPECT_EQ(renderer.viewMap(2, 3)->resolution(), 256);
    EXPECT_EQ(renderer.viewMap(2, 3)->format(), DepthFormat::D16);
    EXPECT_EQ(renderer.viewMap(1, -1)->resolution(), 512);
    // The map of a face holds depths (something was drawn into the -Y face below the light).
    const std::vector<float> depth = renderer.viewMap(2, 3)->readDepth();
    EXPECT_LT(*std::min_element(depth.begin(), depth.end()), 1.0f);
}

// A valid value other than the current one, for any field.
nlohmann::json otherValue(const SettingsField& f, const Settings& s) {
    const nlohmann::json current = f.get(s);
    switch (f.kind) {
        case SettingsFieldKind::Bool: return !current.get<bool>();
        case SettingsFieldKind::Int:
            return f.intChoices.empty() ? nlohmann::json(std::min(int(f.max) - 1, 512)) : nlohmann::json(f.intChoices.front());
        case SettingsFieldKind::Float: return double(float(f.min + (f.max - f.min) * 0.0318309886));
        case SettingsFieldKind::Enum:
            return current == f.choices.back() ? nlohmann::json(f.choices.front()) : nlohmann::json(f.choices.back());
        case SettingsFieldKind::Vec3: return nlohmann::json::array({0.25, f.key.ends_with("color") ? 0.5 : -2.25, 0.125});
        case SettingsFieldKind::String: return current == "none" ? "all" : "none";
        case SettingsFieldKind::StringList: return nlohmann::json::array({"a node the scene lacks"});
    }
    return {};
}

TEST_F(ShadowViews, KeysNotTaggedForAViewOrVariantNeverChangeThem) {
    // The key table's tags drive the planner: a key without the shadow-view tag must never re-render a view, and
    // one without the variant tag never change the main pass's program (else the picture would go stale).
    const Scene scene = loadBuiltin("textbook");
    Settings base = loadShippedPreset("default");
    set(base, "lights.1.type=spot");
    set(base, "lights.1.position=-3,8,2");
    set(base, "lights.1.direction=0.3,-1,-0.2");
    int checked = 0;
    for (const SettingsField* field : settingsFieldsOf(base)) {
        if (field->invalidates & kInvalidatesCamera) continue;  // the camera decides which views are seen
        Settings changed = base;
        if (!field->set(changed, otherValue(*field, base)).empty() || !changed.validate().empty()) continue;
        Renderer renderer;
        const View before = renderView(renderer, scene, base, 64, 48);
        const View after = renderView(renderer, scene, changed, 64, 48);
        if (!(field->invalidates & kInvalidatesShadowView))
            EXPECT_EQ(viewsThatRan(after.stats), 0) << field->key << " re-rendered a view: " << after.stats.shadowPass.reason;
        if (!(field->invalidates & kInvalidatesVariant))
            EXPECT_EQ(after.stats.mainVariants, before.stats.mainVariants) << field->key << " changed the variant";
        ++checked;
    }
    EXPECT_GT(checked, 40);
}

}  // namespace
}  // namespace shadowlab::test
