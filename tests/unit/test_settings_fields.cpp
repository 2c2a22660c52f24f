// The settings table: every key round-trips, every kind of bad value is refused with a message naming the key,
// the value and the allowed range, and a refused value never changes the Settings.
#include "settings/settings_fields.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <set>

using namespace shadowlab;
using nlohmann::json;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A valid value different from the default, for each kind of field.
json otherValue(const SettingsField& f, const Settings& s) {
    json current = f.get(s);
    switch (f.kind) {
        case SettingsFieldKind::Bool: return !current.get<bool>();
        case SettingsFieldKind::Int: {
            if (f.intChoices.empty()) return json(int(f.max) - 1);
            // A choice other than the current one.
            return current == f.intChoices.back() ? json(f.intChoices.front()) : json(f.intChoices.back());
        }
        case SettingsFieldKind::Float: {
            // An awkward value (not a short decimal) inside the range.
            float v = static_cast<float>(f.min + (f.max - f.min) * 0.3183098861837907);
            return json(static_cast<double>(v));
        }
        case SettingsFieldKind::Enum:
            return current == f.choices.back() ? json(f.choices.front()) : json(f.choices.back());
        case SettingsFieldKind::Vec3:  // colours are non-negative, cascade splits increasing distances
            if (f.key.ends_with("splits")) return json::array({1.0 / 3.0, 2.25, 7.5});
            return json::array({1.0 / 3.0, f.key.ends_with("color") ? 2.25 : -2.25, 1e-3});
        case SettingsFieldKind::String: return current == "Spin" ? json("all") : json("Spin");
        case SettingsFieldKind::StringList: return json::array({"Root/City/SkyBox", "B\\/C"});
    }
    return {};
}

// Every field a default (one-light) Settings has: the global ones and light 0's.
std::vector<std::reference_wrapper<const SettingsField>> fieldsOfDefaults() {
    std::vector<std::reference_wrapper<const SettingsField>> out;
    for (const SettingsField* f : settingsFieldsOf(Settings{})) out.emplace_back(*f);
    return out;
}

}  // namespace

TEST(SettingsFields, KeysAreUniqueDocumentedAndFindable) {
    std::set<std::string> keys;
    for (const SettingsField& f : fieldsOfDefaults()) {
        EXPECT_TRUE(keys.insert(f.key).second) << "duplicate key " << f.key;
        EXPECT_FALSE(f.description.empty()) << f.key;
        EXPECT_FALSE(f.allowed.empty()) << f.key;
        EXPECT_EQ(findSettingsField(f.key), &f);
    }
    EXPECT_EQ(keys.size(), 64u);  // every tunable of Settings: 30 global, 34 per light; update when Settings grows
    EXPECT_EQ(findSettingsField("shadow.nope"), nullptr);
    EXPECT_EQ(findSettingsField("Shadow.DepthBias"), nullptr);  // keys are case-sensitive
    EXPECT_EQ(findSettingsField("view")->group(), "");
    EXPECT_EQ(findSettingsField("shadow.depthBias")->group(), "shadow");
    EXPECT_EQ(findSettingsField("shadow.depthBias")->name(), "depthBias");
}

TEST(SettingsFields, EveryKeyRoundTripsItsDefaultAndAnotherValue) {
    const Settings defaults;
    for (const SettingsField& f : fieldsOfDefaults()) {
        SCOPED_TRACE(f.key);
        Settings s;
        EXPECT_EQ(f.set(s, f.get(defaults)), "");
        EXPECT_TRUE(s == defaults);

        json other = otherValue(f, defaults);
        ASSERT_EQ(f.set(s, other), "") << other;
        EXPECT_FALSE(s == defaults) << "set() changed nothing";
        // Stored exactly (floats compare after the same float rounding), and a second set from get() is a no-op.
        Settings again = defaults;
        ASSERT_EQ(f.set(again, f.get(s)), "");
        EXPECT_TRUE(again == s);
        EXPECT_EQ(json::parse(f.get(s).dump()), f.get(s));
    }
}

TEST(SettingsFields, EachFieldTouchesOnlyItsOwnMember) {
    // Setting one field must leave every other field's value alone (catches copy-paste accessors).
    const Settings defaults;
    for (const SettingsField& f : fieldsOfDefaults()) {
        Settings s;
        ASSERT_EQ(f.set(s, otherValue(f, defaults)), "") << f.key;
        for (const SettingsField& g : fieldsOfDefaults())
            if (&g != &f) {
                EXPECT_EQ(g.get(s), g.get(defaults)) << f.key << " changed " << g.key;
            }
    }
}

TEST(SettingsFields, FloatsAreWrittenShortAndReadBackExactly) {
    Settings s;
    s.lights[0].shadow.depthBias = 0.1f;
    EXPECT_EQ(findSettingsField("shadow.depthBias")->get(s).dump(), "0.1");
    // Many random floats of the field's range, through text and back.
    const SettingsField& f = *findSettingsField("shadow.depthBias");
    std::uint32_t state = 12345;
    for (int i = 0; i < 200000; ++i) {
        state = state * 1664525u + 1013904223u;
        float v = std::ldexp(static_cast<float>(state >> 8) / float(1 << 24), static_cast<int>(state % 60) - 40);
        if (state & 1) v = -v;
        s.lights[0].shadow.depthBias = v;
        Settings back;
        ASSERT_EQ(f.set(back, json::parse(f.get(s).dump())), "");
        ASSERT_EQ(back.lights[0].shadow.depthBias, v) << f.get(s).dump();
    }
}

TEST(SettingsFields, IntFieldsAcceptIntegralNumbersOnly) {
    Settings s;
    const SettingsField& res = *findSettingsField("shadow.resolution");
    EXPECT_EQ(res.set(s, json(4096)), "");
    EXPECT_EQ(s.lights[0].shadow.resolution, 4096);
    EXPECT_EQ(res.set(s, json(1024.0)), "");  // 1024.0 is an integer written as a float
    EXPECT_EQ(s.lights[0].shadow.resolution, 1024);

    std::string e = res.set(s, json(2.5));
    EXPECT_TRUE(contains(e, "shadow.resolution")) << e;
    EXPECT_TRUE(contains(e, "2.5")) << e;
    EXPECT_TRUE(contains(e, "not an integer")) << e;
    EXPECT_TRUE(contains(e, "[16, 32768]")) << e;
    EXPECT_EQ(s.lights[0].shadow.resolution, 1024);

    e = res.set(s, json(0));
    EXPECT_TRUE(contains(e, "shadow.resolution: 0 is out of range (allowed integer in [16, 32768])")) << e;
    e = res.set(s, json(std::numeric_limits<std::uint64_t>::max()));
    EXPECT_TRUE(contains(e, "out of range")) << e;
    EXPECT_EQ(s.lights[0].shadow.resolution, 1024);

    const SettingsField& kernel = *findSettingsField("filter.kernel");
    e = kernel.set(s, json(4));
    EXPECT_TRUE(contains(e, "filter.kernel")) << e;
    EXPECT_TRUE(contains(e, "one of 1, 3, 5, 7, 9")) << e;
    EXPECT_EQ(kernel.set(s, json(7)), "");
    EXPECT_EQ(s.filter.kernel, 7);
}

TEST(SettingsFields, FloatFieldsAcceptIntsAndRejectOutOfRange) {
    Settings s;
    const SettingsField& ambient = *findSettingsField("light.ambient");
    EXPECT_EQ(ambient.set(s, json(1)), "");
    EXPECT_EQ(s.ambient, 1.0f);
    std::string e = ambient.set(s, json(1.5));
    EXPECT_EQ(e, "light.ambient: 1.5 is out of range (allowed [0, 1])");
    e = ambient.set(s, json(-1e-9));
    EXPECT_TRUE(contains(e, "light.ambient")) << e;
    EXPECT_EQ(s.ambient, 1.0f);

    e = findSettingsField("shadow.depthBias")->set(s, json(2e6));
    EXPECT_EQ(e, "shadow.depthBias: 2e6 is out of range (allowed [-1e6, 1e6])");
    e = findSettingsField("projection.near")->set(s, json(0));
    EXPECT_EQ(e, "projection.near: 0 is out of range (allowed [1e-4, 1e7])");
}

TEST(SettingsFields, WrongJsonTypesAreRefusedWithKeyValueAndRange) {
    const Settings defaults;
    for (const SettingsField& f : fieldsOfDefaults()) {
        SCOPED_TRACE(f.key);
        // One wrong type per kind: strings for numbers/bools/vectors, numbers for names and lists of names.
        // A string key takes a bare integer as its text (an animation's index): true is its wrong type.
        json bad = f.kind == SettingsFieldKind::Enum || f.kind == SettingsFieldKind::StringList ? json(5)
                   : f.kind == SettingsFieldKind::String                                     ? json(true)
                                                                                             : json("abc");
        Settings s;
        std::string e = f.set(s, bad);
        EXPECT_TRUE(contains(e, f.key + ": ")) << e;
        EXPECT_TRUE(contains(e, bad.dump())) << e;
        EXPECT_TRUE(contains(e, "(allowed " + f.allowed + ")")) << e;
        EXPECT_TRUE(s == defaults);
        // null (what a NaN becomes in a JSON file) and objects are refused too.
        EXPECT_FALSE(f.set(s, json(nullptr)).empty());
        EXPECT_FALSE(f.set(s, json::object()).empty());
        EXPECT_TRUE(s == defaults);
    }
    Settings s;
    EXPECT_EQ(findSettingsField("light.useSceneLight")->set(s, json(1)),
              "light.useSceneLight: expected true or false, got 1 (allowed true or false)");
}

TEST(SettingsFields, NonFiniteNumbersAreRefused) {
    // JSON text cannot hold NaN, and nlohmann refuses 1e400 (number overflow) rather than reading inf...
    json overflow;
    EXPECT_THROW(overflow = json::parse("1e400"), json::exception);
    EXPECT_EQ(json::parse("[1e308]")[0].get<double>(), 1e308);
    // ...but a json value built in code can hold them, so set() must check.
    Settings s;
    const SettingsField& bias = *findSettingsField("shadow.depthBias");
    std::string e = bias.set(s, json(std::numeric_limits<double>::quiet_NaN()));
    EXPECT_EQ(e, "shadow.depthBias: nan is not a finite number (allowed [-1e6, 1e6])");
    e = bias.set(s, json(-std::numeric_limits<double>::infinity()));
    EXPECT_TRUE(contains(e, "-inf")) << e;
    e = findSettingsField("shadow.resolution")->set(s, json(std::numeric_limits<double>::infinity()));
    EXPECT_TRUE(contains(e, "shadow.resolution: inf")) << e;
    e = findSettingsField("light.position")->set(s, json::array({0.0, std::nan(""), 1.0}));
    EXPECT_TRUE(contains(e, "light.position: [0, nan, 1] is not finite")) << e;
    EXPECT_TRUE(s == Settings{});
}

TEST(SettingsFields, EnumsRefuseUnknownNames) {
    Settings s;
    std::string e = findSettingsField("filter.kind")->set(s, json("gaussian"));
    EXPECT_EQ(e, "filter.kind: unknown value \"gaussian\" (allowed one of point, hardware2x2, pcf, poisson, vsm, evsm2, evsm4, msm, pcss)");
    e = findSettingsField("shadow.depthFormat")->set(s, json("D32F"));  // names are case-sensitive
    EXPECT_EQ(e, "shadow.depthFormat: unknown value \"D32F\", did you mean \"d32f\"? (allowed one of d16, d24, d32f)");
    EXPECT_TRUE(s == Settings{});
    EXPECT_EQ(findSettingsField("sampler.addressMode")->set(s, json("clamp")), "");
    EXPECT_EQ(s.sampler.addressMode, AddressMode::ClampToEdge);
}

TEST(SettingsFields, VectorsNeedThreeFiniteComponentsAndDirectionsALength) {
    Settings s;
    const SettingsField& dir = *findSettingsField("light.direction");
    std::string e = dir.set(s, json::array({0, 0, 0}));
    EXPECT_TRUE(contains(e, "light.direction: [0, 0, 0] has (near) zero length")) << e;
    EXPECT_FALSE(dir.set(s, json::array({1e-7, 0, 0})).empty());
    EXPECT_FALSE(dir.set(s, json::array({1e30, 0, 0})).empty());  // would overflow the float dot product
    EXPECT_FALSE(dir.set(s, json::array({1, 2})).empty());
    EXPECT_FALSE(dir.set(s, json::array({1, 2, 3, 4})).empty());
    EXPECT_FALSE(dir.set(s, json::array({1, "2", 3})).empty());
    EXPECT_TRUE(s == Settings{});
    EXPECT_EQ(dir.set(s, json::array({0, -1, 0})), "");
    EXPECT_EQ(s.lights[0].direction, glm::vec3(0, -1, 0));

    e = findSettingsField("camera.position")->set(s, json::array({2e7, 0, 0}));
    EXPECT_TRUE(contains(e, "camera.position: [2e7, 0, 0] has a component beyond the limit")) << e;
    EXPECT_TRUE(contains(e, "|c| <= 1e7")) << e;
}

TEST(SettingsOverride, ParsesJsonOrBareStrings) {
    Settings s;
    EXPECT_EQ(applySettingOverride(s, "filter.kind=poisson"), "");
    EXPECT_EQ(s.filter.kind, FilterKind::Poisson);
    EXPECT_EQ(applySettingOverride(s, "filter.kind=\"pcf\""), "");
    EXPECT_EQ(s.filter.kind, FilterKind::Pcf);
    EXPECT_EQ(applySettingOverride(s, "shadow.resolution=4096"), "");
    EXPECT_EQ(s.lights[0].shadow.resolution, 4096);
    EXPECT_EQ(applySettingOverride(s, "shadow.depthBias=-1.5e3"), "");
    EXPECT_EQ(s.lights[0].shadow.depthBias, -1500.0f);
    EXPECT_EQ(applySettingOverride(s, "light.useSceneLight=true"), "");
    EXPECT_TRUE(s.useSceneLights);
    EXPECT_EQ(applySettingOverride(s, "light.direction=[0,-1,0.5]"), "");
    EXPECT_EQ(s.lights[0].direction, glm::vec3(0, -1, 0.5f));
    EXPECT_EQ(applySettingOverride(s, "camera.target = 1, 2, 3"), "");  // no brackets, spaces around '='
    EXPECT_EQ(s.camera.target, glm::dvec3(1, 2, 3));
    EXPECT_EQ(applySettingOverride(s, "view=light-depth"), "");
    EXPECT_EQ(s.view, ViewMode::LightDepth);
}

TEST(SettingsOverride, BadValuesNameTheKeyAndLeaveSettingsAlone) {
    Settings s;
    const Settings before = s;
    std::string e = applySettingOverride(s, "shadow.depthBias=nan");
    EXPECT_EQ(e, "shadow.depthBias: 'nan' is not a finite number (allowed [-1e6, 1e6])");
    e = applySettingOverride(s, "shadow.depthBias=1e400");  // not JSON (overflow), read by strtod as inf
    EXPECT_TRUE(contains(e, "shadow.depthBias: '1e400' is not a finite number")) << e;
    e = applySettingOverride(s, "light.ambient=-inf");
    EXPECT_TRUE(contains(e, "light.ambient: '-inf'")) << e;
    e = applySettingOverride(s, "shadow.resolution=2.5");
    EXPECT_TRUE(contains(e, "shadow.resolution: 2.5 is not an integer")) << e;
    e = applySettingOverride(s, "shadow.resolution=big");
    EXPECT_TRUE(contains(e, "shadow.resolution: expected an integer, got \"big\"")) << e;
    e = applySettingOverride(s, "filter.kind=gaussian");
    EXPECT_TRUE(contains(e, "filter.kind: unknown value \"gaussian\"")) << e;
    e = applySettingOverride(s, "light.useSceneLight=yes");
    EXPECT_TRUE(contains(e, "light.useSceneLight")) << e;
    e = applySettingOverride(s, "light.direction=[nan,1,0]");
    EXPECT_TRUE(contains(e, "light.direction")) << e;
    e = applySettingOverride(s, "shadow.depthBias=");
    EXPECT_TRUE(contains(e, "shadow.depthBias")) << e;
    EXPECT_TRUE(s == before);
}

TEST(SettingsOverride, UnknownKeysSuggestCloseOnesOrListAll) {
    Settings s;
    std::string e = applySettingOverride(s, "shadow.depthBais=3");
    EXPECT_TRUE(contains(e, "unknown setting 'shadow.depthBais'")) << e;
    EXPECT_TRUE(contains(e, "did you mean shadow.depthBias")) << e;
    e = applySettingOverride(s, "depthBias=3");  // group forgotten
    EXPECT_TRUE(contains(e, "shadow.depthBias")) << e;
    e = applySettingOverride(s, "shadow.bias=3");  // part of a name
    EXPECT_TRUE(contains(e, "did you mean filter.momentBias, shadow.depthBias, shadow.slopeScaledDepthBias, "
                            "shadow.depthBiasClamp, shadow.receiverPlaneBias?"))
        << e;
    e = applySettingOverride(s, "filter.Kind=pcf");  // wrong case
    EXPECT_TRUE(contains(e, "filter.kind")) << e;
    e = applySettingOverride(s, "zzzzzzzzzz=1");
    EXPECT_TRUE(contains(e, "valid keys: ambient, useSceneLights,")) << e;
    EXPECT_TRUE(contains(e, "lights.#.shadow.depthBias,")) << e;
    EXPECT_TRUE(contains(e, "view")) << e;
    e = applySettingOverride(s, "shadow.depthBias");
    EXPECT_TRUE(contains(e, "key=value")) << e;
    EXPECT_TRUE(s == Settings{});
}

TEST(SettingsValidate, DefaultsAreValid) { EXPECT_TRUE(Settings{}.validate().empty()); }

TEST(SettingsValidate, ReportsEveryBadFieldByKey) {
    Settings s;
    s.lights[0].shadow.resolution = 0;                                   // HARD_CASES 15
    s.lights[0].shadow.depthBias = std::numeric_limits<float>::quiet_NaN();  // HARD_CASES 14
    s.lights[0].direction = glm::vec3(0.0f);                       // HARD_CASES 14
    s.lights[0].spotConeDeg = 180.0f;                              // HARD_CASES 8
    s.lights[0].projection.orthoSize = 0.0f;                             // HARD_CASES 14
    s.filter.kind = static_cast<FilterKind>(42);
    auto problems = s.validate();
    ASSERT_EQ(problems.size(), 6u);
    std::string all;
    for (const auto& p : problems) all += p + "\n";
    for (const char* key : {"shadow.resolution: 0", "shadow.depthBias: nan", "lights.0.direction: [0, 0, 0]",
                            "lights.0.spotConeDeg: 180", "projection.orthoSize: 0", "filter.kind: unknown value"})
        EXPECT_TRUE(contains(all, key)) << key << " missing in\n" << all;
    for (const auto& p : problems) EXPECT_TRUE(contains(p, "(allowed ")) << p;
}

TEST(SettingsValidate, CrossFieldRules) {
    Settings s;
    s.lights[0].projection.nearPlane = 10.0f;
    s.lights[0].projection.farPlane = 5.0f;
    EXPECT_TRUE(s.validate().empty()) << "auto-fit ignores near/far";
    s.lights[0].projection.autoFit = false;
    auto problems = s.validate();
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0],
              "lights.0.projection.near: 10 is not less than lights.0.projection.far 5 (allowed near < far)");
    s.lights[0].projection.farPlane = 10.0f;
    EXPECT_EQ(s.validate().size(), 1u);
    s.lights[0].projection.farPlane = 10.5f;
    EXPECT_TRUE(s.validate().empty());

    // A light's size: a radius up to 1e6 for spot and point lights, an angle up to 90 degrees for a directional one.
    s.lights[0].size = 120.0f;
    problems = s.validate();
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "lights.0.size: 120 degrees is too wide for a directional light's angular diameter "
                           "(allowed [0, 90] for a directional light; a spot or point light's radius up to 1e6)");
    s.lights[0].type = LightType::Point;
    EXPECT_TRUE(s.validate().empty()) << "a point light's radius of 120";
    s.lights[0].type = LightType::Directional;
    s.lights[0].size = 90.0f;
    EXPECT_TRUE(s.validate().empty());

    s.camera.position = s.camera.target = glm::vec3(1.0f);
    EXPECT_TRUE(s.validate().empty()) << "auto-frame ignores position/target";
    s.camera.autoFrame = false;
    problems = s.validate();
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_TRUE(contains(problems[0], "camera.target")) << problems[0];
}
