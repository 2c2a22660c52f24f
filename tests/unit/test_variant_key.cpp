// The main pass's variant key derives from the key table: every key tagged kInvalidatesVariant changes the key for
// some value in some light set, and no other key ever changes it. A new key tagged for the shader that the key
// ignores (or a key the key reads without the tag) fails here.
#include "key_values.h"
#include "light/scene_lights.h"
#include "settings/settings_fields.h"
#include "shading/variant_key.h"

#include <gtest/gtest.h>

using namespace shadowlab;

namespace {

// Light sets in which each variant key can show: two 2D casters of one size (a size or format change splits their
// array), a PCF filter (kernel, receiver plane), a cascaded sun as light 0 or light 1 (the cascade count), and the
// same without any light's normal offset or receiver-plane bias (so one light's turns the define on), and a moments
// technique (its mips).
std::vector<Settings> lightSets() {
    Settings a;
    a.filter.kind = FilterKind::Pcf;
    LightSettings sun;
    sun.type = LightType::Directional;
    LightSettings spot;
    spot.type = LightType::Spot;
    spot.position = {2.0f, 6.0f, 1.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    a.lights = {sun, spot};
    Settings b = a;
    b.lights[0].projection.fit = ProjectionFit::Cascades;
    Settings c = b;
    std::swap(c.lights[0], c.lights[1]);
    std::vector<Settings> sets = {a, b, c};
    for (Settings plain : {a, c}) {
        for (LightSettings& l : plain.lights) {
            l.shadow.normalOffset = 0.0f;
            l.shadow.receiverPlaneBias = false;
        }
        sets.push_back(plain);
    }
    Settings moments = a;  // a moments technique (filter.momentMips)
    moments.filter.kind = FilterKind::Vsm;
    sets.push_back(moments);
    return sets;
}

// The scene's own light (useSceneLights): one point light.
Scene sceneWithALight() {
    Scene scene;
    SceneLight lamp;
    lamp.type = SceneLightType::Point;
    scene.lights = {lamp};
    return scene;
}

MainVariantKey keyOf(const Settings& requested, const Scene& scene) {
    return mainVariantKey(withEffectiveLights(requested, scene));
}

}  // namespace

TEST(VariantKey, EveryKeyTaggedForTheShaderChangesItAndNoOtherKeyDoes) {
    const Scene scene = sceneWithALight();
    int tagged = 0, untagged = 0;
    for (const SettingsField* field : settingsFieldsOf(lightSets().front())) {
        const bool variant = field->invalidates & kInvalidatesVariant;
        bool changes = false;
        int values = 0;
        for (const Settings& base : lightSets()) {
            if (field->light >= int(base.lights.size())) continue;  // setting it would add a light
            const MainVariantKey before = keyOf(base, scene);
            for (const nlohmann::json& value : test::otherValues(*field, field->get(base))) {
                Settings changed = base;
                if (!field->set(changed, value).empty() || !changed.validate().empty()) continue;
                ++values;
                const bool differs = keyOf(changed, scene) != before;
                changes = changes || differs;
                if (!variant)
                    EXPECT_FALSE(differs) << field->key << "=" << value.dump()
                                          << " changed the variant without the key table's variant tag";
            }
        }
        EXPECT_GT(values, 0) << field->key << ": no value to try";
        if (variant) EXPECT_TRUE(changes) << field->key << " is tagged as changing the shader but no value changes "
                                          << "the variant key (shading/variant_key.cpp)";
        ++(variant ? tagged : untagged);
    }
    EXPECT_GE(tagged, 12);
    EXPECT_GT(untagged, 25);
}

TEST(VariantKey, OnlyTheVariantTaggedKeysReachTheKeysInputs) {
    Settings s = lightSets()[1];  // a cascaded sun, a spot
    s.lights[1].intensity = 7.0f;            // untagged: stays at its default
    s.lights[1].shadow.normalOffset = 2.0f;  // tagged: carried over
    const Settings inputs = variantInputs(s);
    EXPECT_EQ(inputs.lights[1].intensity, LightSettings{}.intensity);
    EXPECT_EQ(inputs.lights[1].shadow.normalOffset, 2.0f);
    EXPECT_EQ(inputs.lights[0].projection.fit, ProjectionFit::Cascades);
    const MainVariantKey key = mainVariantKey(s);
    EXPECT_EQ(key.lights.directional, 1);
    EXPECT_EQ(key.lights.spot, 1);
    EXPECT_EQ(key.lights.mapArrays2D, 1);  // one size and format: one array
    EXPECT_EQ(key.lights.cascades, s.lights[0].projection.cascadeCount);
    EXPECT_TRUE(key.normalOffset);
}
