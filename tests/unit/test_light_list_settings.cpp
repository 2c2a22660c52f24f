// Schema 2: settings hold a list of lights, addressed by index in keys ("lights.2.shadow.depthBias"); the schema-1
// keys stay aliases of light 0; each key says what its change invalidates.
#include "settings/preset_io.h"
#include "settings/settings_fields.h"

#include <gtest/gtest.h>

#include <set>

namespace shadowlab {
namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(LightListSettings, IndexedKeysAddLightsOneAtATime) {
    Settings s;
    ASSERT_EQ(applySettingOverride(s, "lights.1.type=point"), "");
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[1].type, LightType::Point);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    ASSERT_EQ(applySettingOverride(s, "lights.1.shadow.depthBias=20"), "");
    EXPECT_EQ(s.lights[1].shadow.depthBias, 20.0f);
    EXPECT_EQ(s.lights[0].shadow.depthBias, 2.0f);

    const Settings before = s;
    std::string e = applySettingOverride(s, "lights.5.type=spot");
    EXPECT_TRUE(contains(e, "lights.5.type: there is no light 5 (the settings have 2 lights; lights.2.* adds one"))
        << e;
    e = applySettingOverride(s, "lights.2.spotConeDeg=400");  // a refused value adds no light
    EXPECT_TRUE(contains(e, "lights.2.spotConeDeg: 400 is out of range")) << e;
    EXPECT_TRUE(s == before);
    EXPECT_EQ(findSettingsField("lights.01.type"), nullptr);  // one spelling per key
    EXPECT_EQ(findSettingsField("lights.32.type"), nullptr);  // beyond kMaxLights
    EXPECT_EQ(findSettingsField("lights.1"), nullptr);
    EXPECT_NE(findSettingsField("lights.31.castsShadows"), nullptr);
}

TEST(LightListSettings, Schema1KeysAreAliasesOfLightZero) {
    Settings viaAlias, viaIndex;
    for (const SettingsField& alias : schema1Aliases()) {
        SCOPED_TRACE(alias.key);
        const SettingsField* target = findSettingsField(alias.aliasOf);
        ASSERT_NE(target, nullptr);
        EXPECT_EQ(findSettingsField(alias.key), &alias);
        EXPECT_EQ(alias.get(viaAlias), target->get(viaIndex));
    }
    ASSERT_EQ(applySettingOverride(viaAlias, "shadow.depthBias=4"), "");
    ASSERT_EQ(applySettingOverride(viaIndex, "lights.0.shadow.depthBias=4"), "");
    ASSERT_EQ(applySettingOverride(viaAlias, "light.ambient=0.3"), "");
    ASSERT_EQ(applySettingOverride(viaIndex, "ambient=0.3"), "");
    ASSERT_EQ(applySettingOverride(viaAlias, "light.useSceneLight=true"), "");
    ASSERT_EQ(applySettingOverride(viaIndex, "useSceneLights=true"), "");
    EXPECT_TRUE(viaAlias == viaIndex);
    // A message names the key as the user typed it.
    EXPECT_TRUE(contains(applySettingOverride(viaAlias, "shadow.depthBias=nope"), "shadow.depthBias: expected"));
}

TEST(LightListSettings, PresetsCarryEveryLight) {
    Settings s;
    for (const char* set : {"lights.1.type=spot", "lights.1.position=1,5,2", "lights.1.castsShadows=false",
                            "lights.2.type=point", "lights.2.range=12", "lights.2.color=1,0.5,0.25",
                            "lights.2.shadow.resolution=512", "lights.2.projection.autoFit=false",
                            "lights.2.projection.near=0.05", "lights.2.projection.far=30"})
        ASSERT_EQ(applySettingOverride(s, set), "") << set;
    const PresetLoadResult back = presetFromText(presetToText(s, "three"));
    ASSERT_TRUE(back.settings) << back.errors.front();
    EXPECT_TRUE(*back.settings == s);
    EXPECT_TRUE(back.warnings.empty());

    // The list replaces the base's lights; a light keeps the base's values for keys it leaves out.
    nlohmann::json j = presetToJson(s);
    j["lights"].erase(1);
    j["lights"][1].erase("range");
    Settings base = s;
    base.lights[1].range = 7.0f;
    const PresetLoadResult fewer = presetFromJson(j, base);
    ASSERT_TRUE(fewer.settings);
    ASSERT_EQ(fewer.settings->lights.size(), 2u);
    EXPECT_EQ(fewer.settings->lights[1].type, LightType::Point);
    EXPECT_EQ(fewer.settings->lights[1].range, 7.0f);
}

TEST(LightListSettings, BadLightListsAreErrorsNamingTheLight) {
    nlohmann::json j = presetToJson(Settings{});
    j["lights"] = "sun";
    EXPECT_TRUE(contains(presetFromJson(j).errors.at(0), "lights: expected a list of lights")) << presetFromJson(j).errors.at(0);
    j["lights"] = nlohmann::json::array({nlohmann::json::object(), 3});
    EXPECT_TRUE(contains(presetFromJson(j).errors.at(0), "lights.1: expected an object, got 3"));
    j["lights"] = nlohmann::json::array();
    for (int i = 0; i < 33; ++i) j["lights"].push_back(nlohmann::json::object());
    EXPECT_TRUE(contains(presetFromJson(j).errors.at(0), "lights: 33 lights (allowed at most 32)"));
    j["lights"] = nlohmann::json::array({{{"shadow", {{"depthBias", "big"}}}}});
    EXPECT_TRUE(contains(presetFromJson(j).errors.at(0), "lights.0.shadow.depthBias: expected a number"));
    j["lights"] = nlohmann::json::array({{{"shadoww", {{"depthBias", 1}}}}});
    const PresetLoadResult typo = presetFromJson(j);
    ASSERT_TRUE(typo.settings);
    EXPECT_TRUE(contains(typo.warnings.at(0), "unknown key 'lights.0.shadoww' ignored")) << typo.warnings.at(0);
    // Schema 1 has no list: a "lights" key there is unknown, its one light comes from "light"/"shadow"/"projection".
    nlohmann::json v1 = {{"schema", "shadowlab-preset"}, {"schemaVersion", 1}, {"shadow", {{"depthBias", 5}}},
                         {"lights", nlohmann::json::array()}};
    Settings two;
    two.lights.resize(2);
    const PresetLoadResult old = presetFromJson(v1, two);
    ASSERT_TRUE(old.settings);
    EXPECT_EQ(old.settings->lights.size(), 1u);
    EXPECT_EQ(old.settings->lights[0].shadow.depthBias, 5.0f);
    EXPECT_TRUE(contains(old.warnings.at(0), "unknown key 'lights'"));
}

TEST(LightListSettings, DiffsNameKeysAndWhatTheyInvalidate) {
    Settings a;
    a.lights.resize(2);
    Settings b = a;
    b.lights[1].shadow.depthBias = 9.0f;
    SettingsDiff d = diffSettings(a, b);
    ASSERT_EQ(d.keys, std::vector<std::string>{"lights.1.shadow.depthBias"});
    EXPECT_EQ(d.invalidates, unsigned(kInvalidatesShadowView));
    b = a;
    b.filter.kernel = 5;
    b.sampler.addressMode = AddressMode::Wrap;
    d = diffSettings(a, b);
    EXPECT_EQ(d.invalidates, unsigned(kInvalidatesVariant | kInvalidatesSampler));
    b = a;
    b.lights[0].intensity = 3.0f;  // the picture only
    EXPECT_EQ(diffSettings(a, b).invalidates, unsigned(kInvalidatesNothingElse));
    EXPECT_EQ(diffSettings(a, b).keys.size(), 1u);
    b = a;
    b.lights.pop_back();
    d = diffSettings(a, b);
    EXPECT_EQ(d.keys, std::vector<std::string>{"lights.1"});
    EXPECT_TRUE(d.invalidates & kInvalidatesShadowView);
    EXPECT_TRUE(diffSettings(a, a).empty());
    EXPECT_EQ(diffLight(a.lights[0], b.lights[0]).keys.size(), 0u);
}

TEST(LightListSettings, KeyListingShowsLightKeysOnceAsAPattern) {
    std::set<std::string> patterns;
    for (const SettingsField* f : settingsKeyListing()) EXPECT_TRUE(patterns.insert(f->pattern()).second) << f->pattern();
    EXPECT_TRUE(patterns.count("lights.#.shadow.depthBias"));
    EXPECT_TRUE(patterns.count("lights.#.castsShadows"));
    EXPECT_TRUE(patterns.count("filter.kind"));
    EXPECT_FALSE(patterns.count("lights.1.type"));
    EXPECT_EQ(findSettingsField("lights.3.projection.near")->pattern(), "lights.#.projection.near");
}

}  // namespace
}  // namespace shadowlab
