// Presets: JSON shape, partial presets over a base, warnings for unknown keys, all-or-nothing errors, exact float
// round trips through files, atomic saves that never lose the previous file, and the shipped presets.
#include "../support/as_unprivileged_user.h"
#include "light/scene_lights.h"
#include "scene/builtin_scenes.h"
#include "settings/preset_io.h"
#include "settings/preset_scene.h"
#include "settings/settings_fields.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

using namespace shadowlab;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string joinLines(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

// A fresh folder per test, removed afterwards (permissions restored first, for the read-only test).
struct TempFolder {
    fs::path path;
    TempFolder() {
        path = fs::temp_directory_path() /
               ("shadowlab-presets-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() {
        std::error_code ec;
        fs::permissions(path, fs::perms::owner_all, ec);
        fs::remove_all(path, ec);
    }
    std::string operator/(const std::string& name) const { return (path / name).string(); }
};

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void writeFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::set<std::string> filesIn(const fs::path& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
    return names;
}

json minimalPreset() { return json{{"schema", "shadowlab-preset"}, {"schemaVersion", 1}}; }

// Settings with floats that do not survive a careless float -> text -> float trip.
Settings awkwardSettings() {
    Settings s;
    s.lights[0].shadow.resolution = 3000;
    s.lights[0].shadow.format = DepthFormat::D24;
    s.lights[0].shadow.depthBias = 0.1f;
    s.lights[0].shadow.slopeScaledDepthBias = 1e-7f;
    s.lights[0].shadow.depthBiasClamp = std::numeric_limits<float>::denorm_min();  // 1.4e-45, the smallest denormal
    s.lights[0].shadow.normalOffset = 1e-40f;                                     // another denormal
    s.lights[0].shadow.cullMode = CullMode::Front;  // not the default (none)
    s.lights[0].size = 0.53f;                       // the sun's angular diameter
    s.reference.softRays = 1000;
    s.lights[0].type = LightType::Spot;
    s.lights[0].direction = {1.0f / 3.0f, -std::numeric_limits<float>::min(), -0.7f};
    s.lights[0].position = {1e7f, -9999999.0f, 16777217.0f / 4.0f};
    s.lights[0].spotConeDeg = std::nextafter(170.0f, 0.0f);
    s.lights[0].intensity = 3.14159274f;
    s.ambient = std::nextafter(1.0f, 0.0f);  // 0.99999994
    s.useSceneLights = true;
    s.lights[0].projection.autoFit = false;
    s.lights[0].projection.orthoSize = 123.456f;
    s.lights[0].projection.nearPlane = 1e-4f;
    s.lights[0].projection.farPlane = 1e8f;
    s.lights[0].projection.depthClamp = false;
    s.sampler.addressMode = AddressMode::Wrap;
    s.sampler.borderDepth = 0.3f;
    s.filter.kind = FilterKind::Hardware2x2;
    s.filter.kernel = 9;
    s.filter.poissonRadius = 0.7f;
    s.camera.autoFrame = false;
    s.camera.position = {-0.1f, 0.2f, 0.3f};
    s.camera.target = {1e-30f, 5e-39f, -0.0f};
    s.camera.fovYDeg = 59.999996f;
    s.camera.sceneCamera = 3;
    s.casters.excluded = {"City/SkyBox", "Ro\\/ot/#4", "\xc3\xa9t\xc3\xa9"};
    s.view = ViewMode::LightDepth;
    return s;
}

}  // namespace

TEST(Presets, JsonHasTheDocumentedShape) {
    json j = presetToJson(Settings{}, "my preset", "what it shows");
    EXPECT_EQ(j["schema"], "shadowlab-preset");
    EXPECT_EQ(j["schemaVersion"], 2);
    EXPECT_EQ(j["name"], "my preset");
    EXPECT_EQ(j["description"], "what it shows");
    ASSERT_TRUE(j["lights"].is_array());
    ASSERT_EQ(j["lights"].size(), 1u);
    const json& light = j["lights"][0];
    EXPECT_EQ(light["type"], "directional");
    EXPECT_EQ(light["shadow"]["resolution"], 2048);
    EXPECT_EQ(light["shadow"]["depthFormat"], "d32f");
    EXPECT_EQ(light["direction"], json::parse("[-0.4, -1.0, -0.3]"));
    EXPECT_EQ(light["projection"]["near"], 0.1);
    EXPECT_EQ(j["ambient"], 0.15);
    EXPECT_EQ(j["useSceneLights"], false);
    EXPECT_EQ(j["sampler"]["addressMode"], "border");
    EXPECT_EQ(j["filter"]["kind"], "pcf");
    EXPECT_EQ(j["camera"]["fovYDeg"], 45.0);
    EXPECT_EQ(j["view"], "lit");
    // Exactly the meta keys, ambient, useSceneLights, lights, the groups and "view" at the top; every table key once.
    auto leavesOf = [](const json& object) {
        std::size_t leaves = 0;
        for (const auto& [key, value] : object.items())
            if (key != "lights") leaves += value.is_object() ? value.size() : 1;
        return leaves;
    };
    EXPECT_EQ(leavesOf(j) - 4 + leavesOf(light), settingsFieldsOf(Settings{}).size());
    EXPECT_EQ(j.size(), 4u + 3u + 6u + 1u);  // groups: sampler, filter, camera, casters, animation, reference
    EXPECT_EQ(j["camera"]["sceneCamera"], -1);
    EXPECT_EQ(j["casters"]["excluded"], json::array());

    // The file text keeps Settings order and short floats.
    std::string text = presetToText(Settings{});
    EXPECT_LT(text.find("\"schema\""), text.find("\"lights\""));
    EXPECT_LT(text.find("\"type\""), text.find("\"shadow\""));
    EXPECT_LT(text.find("\"shadow\""), text.find("\"projection\""));
    EXPECT_LT(text.find("\"projection\""), text.find("\"sampler\""));
    EXPECT_LT(text.find("\"camera\""), text.find("\"view\""));
    EXPECT_TRUE(contains(text, "\"direction\": [-0.4, -1.0, -0.3]")) << text;
    EXPECT_TRUE(contains(text, "\"near\": 0.1,")) << text;
    EXPECT_EQ(json::parse(text), presetToJson(Settings{}));
}

TEST(Presets, RoundTripThroughJson) {
    for (const Settings& s : {Settings{}, awkwardSettings()}) {
        PresetLoadResult r = presetFromJson(json::parse(presetToJson(s, "n", "d").dump()));
        ASSERT_TRUE(r.errors.empty()) << joinLines(r.errors);
        EXPECT_TRUE(r.warnings.empty()) << joinLines(r.warnings);
        ASSERT_TRUE(r.settings);
        EXPECT_TRUE(*r.settings == s);
        EXPECT_EQ(r.name, "n");
        EXPECT_EQ(r.description, "d");
    }
}

TEST(Presets, AbsentKeysKeepTheBaseValues) {
    Settings base;
    base.lights[0].shadow.resolution = 512;
    base.filter.kind = FilterKind::Poisson;
    json preset = minimalPreset();
    preset["shadow"] = {{"depthBias", 7}};
    preset["view"] = "shadow";
    PresetLoadResult r = presetFromJson(preset, base);
    ASSERT_TRUE(r.settings) << joinLines(r.errors);
    Settings expected = base;
    expected.lights[0].shadow.depthBias = 7.0f;
    expected.view = ViewMode::Shadow;
    EXPECT_TRUE(*r.settings == expected);
    EXPECT_TRUE(r.name.empty());
}

TEST(Presets, UnknownKeysAreWarningsNamingThem) {
    json preset = minimalPreset();
    preset["shadow"] = {{"depthBais", 3}, {"resolution", 1024}};
    preset["lighting"] = {{"x", 1}};
    preset["filter.kind"] = "point";  // dotted key at the top level
    PresetLoadResult r = presetFromJson(preset);
    ASSERT_TRUE(r.settings) << joinLines(r.errors);
    EXPECT_EQ(r.settings->lights[0].shadow.resolution, 1024);
    EXPECT_EQ(r.settings->filter.kind, FilterKind::Pcf);
    std::string all = joinLines(r.warnings);
    ASSERT_EQ(r.warnings.size(), 3u) << all;
    EXPECT_TRUE(contains(all, "unknown key 'shadow.depthBais' ignored (did you mean shadow.depthBias?)")) << all;
    EXPECT_TRUE(contains(all, "unknown key 'lighting'")) << all;
    EXPECT_TRUE(contains(all, "'filter.kind'")) << all;
    EXPECT_TRUE(contains(all, "\"filter\": {\"kind\"")) << all;
}

TEST(Presets, AnyErrorMeansNoSettingsAtAll) {
    json preset = minimalPreset();
    preset["shadow"] = {{"resolution", 1024}, {"depthBias", "lots"}, {"normalOffset", 99}};
    preset["light"] = {{"direction", {0, 0, 0}}};
    preset["view"] = "3d";
    PresetLoadResult r = presetFromJson(preset);
    EXPECT_FALSE(r.settings);
    std::string all = joinLines(r.errors);
    ASSERT_EQ(r.errors.size(), 4u) << all;
    EXPECT_TRUE(contains(all, "shadow.depthBias: expected a number, got \"lots\"")) << all;
    EXPECT_TRUE(contains(all, "shadow.normalOffset: 99 is out of range (allowed [0, 16])")) << all;
    EXPECT_TRUE(contains(all, "light.direction: [0, 0, 0] has (near) zero length")) << all;
    EXPECT_TRUE(contains(all, "view: unknown value \"3d\"")) << all;

    preset = minimalPreset();
    preset["shadow"] = 5;
    r = presetFromJson(preset);
    EXPECT_FALSE(r.settings);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_TRUE(contains(r.errors[0], "shadow: expected an object")) << r.errors[0];

    preset = minimalPreset();
    preset["name"] = 3;
    EXPECT_FALSE(presetFromJson(preset).settings);
}

TEST(Presets, CrossFieldRulesAreErrors) {
    json preset = minimalPreset();
    preset["projection"] = {{"autoFit", false}, {"near", 10}, {"far", 5}};
    PresetLoadResult r = presetFromJson(preset);
    EXPECT_FALSE(r.settings);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_TRUE(contains(r.errors[0], "lights.0.projection.near: 10 is not less than lights.0.projection.far 5"))
        << r.errors[0];
}

TEST(Presets, SchemaAndVersionAreChecked) {
    auto errorsOf = [](const json& preset) {
        PresetLoadResult r = presetFromJson(preset);
        EXPECT_FALSE(r.settings);
        return joinLines(r.errors);
    };
    json p = minimalPreset();
    p.erase("schemaVersion");
    EXPECT_TRUE(contains(errorsOf(p), "schemaVersion: missing (allowed 1 to 2)"));
    p["schemaVersion"] = 3;
    std::string e = errorsOf(p);
    EXPECT_TRUE(contains(e, "schemaVersion: 3 is newer than this ShadowLab understands")) << e;
    p["schemaVersion"] = "1";
    EXPECT_TRUE(contains(errorsOf(p), "schemaVersion: expected an integer, got \"1\""));
    p["schemaVersion"] = 0;
    EXPECT_TRUE(contains(errorsOf(p), "schemaVersion: 0 is not a valid version"));
    p["schemaVersion"] = 1;
    p["schema"] = "other-tool";
    EXPECT_TRUE(contains(errorsOf(p), "schema: \"other-tool\" is not a ShadowLab preset"));
    p.erase("schema");
    EXPECT_TRUE(contains(errorsOf(p), "schema: missing"));
    EXPECT_TRUE(contains(errorsOf(json::array()), "a preset must be a JSON object, got array"));
}

TEST(Presets, FileRoundTripIsExact) {
    TempFolder dir;
    const std::string path = dir / "awkward.json";
    const Settings s = awkwardSettings();
    ASSERT_EQ(s.validate(), std::vector<std::string>{});
    ASSERT_EQ(savePresetFile(path, s, "awkward", "floats that bite\nwith a \"quote\" and ünïcode"), "");
    PresetLoadResult r = loadPresetFile(path);
    ASSERT_TRUE(r.settings) << joinLines(r.errors);
    EXPECT_TRUE(r.warnings.empty()) << joinLines(r.warnings);
    EXPECT_TRUE(*r.settings == s);
    EXPECT_EQ(r.settings->lights[0].shadow.depthBiasClamp, std::numeric_limits<float>::denorm_min());
    EXPECT_TRUE(std::signbit(r.settings->camera.target.z));  // -0.0 survives too
    EXPECT_EQ(r.name, "awkward");
    EXPECT_EQ(r.description, "floats that bite\nwith a \"quote\" and ünïcode");
    // Short decimals stay short in the file.
    std::string text = readFile(path);
    EXPECT_TRUE(contains(text, "\"depthBias\": 0.1,")) << text;
    EXPECT_TRUE(contains(text, "\"slopeScaledDepthBias\": 1e-07,")) << text;
    // Saving again gives the same bytes, and leaves no temporary behind.
    ASSERT_EQ(savePresetFile(path, *r.settings, r.name, r.description), "");
    EXPECT_EQ(readFile(path), text);
    EXPECT_EQ(filesIn(dir.path), std::set<std::string>{"awkward.json"});
}

TEST(Presets, APresetRecordsItsSceneAndCameraAndOldPresetsLoadUnchanged) {
    TempFolder dir;
    const std::string path = dir / "tuned.json";
    Settings s;
    s.camera.autoFrame = false;
    s.camera.position = {1.25, 2.5, -3.0};
    s.camera.target = {0.5, 0.0, 0.25};
    s.camera.fovYDeg = 35.0f;
    ASSERT_EQ(savePresetFile(path, s, "tuned", "", "/data/scenes/Lantern.gltf"), "");
    EXPECT_EQ(json::parse(readFile(path))["scene"], "/data/scenes/Lantern.gltf");
    PresetLoadResult r = loadPresetFile(path);
    ASSERT_TRUE(r.settings) << joinLines(r.errors);
    EXPECT_TRUE(r.warnings.empty()) << joinLines(r.warnings);
    EXPECT_EQ(r.scene, "/data/scenes/Lantern.gltf");
    EXPECT_EQ(r.settings->camera, s.camera);

    // A preset written before presets had a scene: no key, no warning, the same settings as before.
    json old = presetToJson(s, "old");
    ASSERT_FALSE(old.contains("scene"));
    PresetLoadResult o = presetFromJson(old);
    ASSERT_TRUE(o.settings) << joinLines(o.errors);
    EXPECT_TRUE(o.warnings.empty()) << joinLines(o.warnings);
    EXPECT_EQ(o.scene, "");
    EXPECT_EQ(*o.settings, s);

    // A scene that is not a string is an error naming the key.
    json bad = presetToJson(s);
    bad["scene"] = 3;
    PresetLoadResult b = presetFromJson(bad);
    EXPECT_FALSE(b.settings);
    ASSERT_FALSE(b.errors.empty());
    EXPECT_TRUE(contains(b.errors.front(), "scene: expected a string")) << b.errors.front();
}

// Presets written before lights had a size and the reference a ray count: no warning, hard lights (size 0) and the
// default 256 rays, every other value as saved.
TEST(Presets, PresetsWithoutLightSizesLoadAsHardLights) {
    Settings s = awkwardSettings();
    s.lights.push_back(LightSettings{});
    s.lights[1].type = LightType::Point;
    s.lights[0].size = s.lights[1].size = 0.0f;
    s.reference = ReferenceSettings{};
    json old = presetToJson(s, "old");
    for (json& light : old["lights"]) {
        ASSERT_TRUE(light.contains("size"));
        light.erase("size");
    }
    ASSERT_EQ(old.erase("reference"), 1u);
    const PresetLoadResult r = presetFromJson(old);
    ASSERT_TRUE(r.settings) << joinLines(r.errors);
    EXPECT_TRUE(r.warnings.empty()) << joinLines(r.warnings);
    EXPECT_EQ(*r.settings, s);
    EXPECT_EQ(r.settings->lights[1].size, 0.0f);
    EXPECT_EQ(r.settings->reference.softRays, 256);
}

TEST(Presets, OnAnotherSceneTheCameraAutoFramesAndSaysSo) {
    Settings s;
    s.camera.autoFrame = false;
    s.camera.position = {1.0, 2.0, 3.0};

    // The scene it was tuned on (or one that records none): the camera comes back as saved, nothing to say.
    for (const std::string& recorded : {std::string("builtin:textbook"), std::string()}) {
        Settings same = s;
        EXPECT_EQ(adaptPresetToScene(same, recorded, "builtin:textbook"), "");
        EXPECT_EQ(same, s);
    }
    // Another scene: auto-framed, and the note names both scenes.
    Settings other = s;
    const std::string note = adaptPresetToScene(other, "builtin:textbook", "builtin:contact");
    EXPECT_TRUE(other.camera.autoFrame);
    EXPECT_EQ(other.camera.fovYDeg, s.camera.fovYDeg);
    EXPECT_TRUE(contains(note, "builtin:textbook") && contains(note, "builtin:contact")) << note;
    EXPECT_TRUE(contains(note, "auto-framed")) << note;

    // Two spellings of one file are the same scene.
    TempFolder dir;
    writeFile(dir / "a.gltf", "{}");
    EXPECT_TRUE(samePresetScene(dir / "a.gltf", (dir.path / "." / "a.gltf").string()));
    EXPECT_FALSE(samePresetScene(dir / "a.gltf", dir / "b.gltf"));
}

TEST(Presets, SaveKeepsPermissionsOfTheReplacedFile) {
    TempFolder dir;
    const std::string path = dir / "p.json";
    ASSERT_EQ(savePresetFile(path, Settings{}), "");
    ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
    ASSERT_EQ(savePresetFile(path, awkwardSettings()), "");
    struct stat st {};
    ASSERT_EQ(::stat(path.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
}

TEST(Presets, FailedSaveToMissingFolderSaysSo) {
    TempFolder dir;
    const std::string path = dir / "no-such-folder/p.json";
    std::string e = savePresetFile(path, Settings{});
    EXPECT_TRUE(contains(e, "cannot save preset '" + path + "'")) << e;
    EXPECT_TRUE(contains(e, "no-such-folder' does not exist")) << e;
    EXPECT_FALSE(fs::exists(dir.path / "no-such-folder"));

    e = savePresetFile(dir / "", Settings{});  // a folder, not a file
    EXPECT_FALSE(e.empty());
}

TEST(Presets, FailedWriteLeavesThePreviousFileIntact) {
    // A write that fails half-way (file size limit, like a full disk), which also works when tests run as root.
    TempFolder dir;
    const std::string path = dir / "keep.json";
    ASSERT_EQ(savePresetFile(path, Settings{}, "old"), "");
    const std::string before = readFile(path);

    struct rlimit old {};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
    auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);  // get EFBIG instead of being killed
    struct rlimit small = old;
    small.rlim_cur = 256;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    std::string e = savePresetFile(path, awkwardSettings(), "new", std::string(4000, 'x'));
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);

    EXPECT_TRUE(contains(e, "cannot save preset")) << e;
    EXPECT_TRUE(contains(e, "write")) << e;
    EXPECT_EQ(readFile(path), before);
    EXPECT_EQ(filesIn(dir.path), std::set<std::string>{"keep.json"}) << "temporary file left behind";
    PresetLoadResult r = loadPresetFile(path);
    ASSERT_TRUE(r.settings);
    EXPECT_EQ(r.name, "old");
}

TEST(Presets, FailedSaveInReadOnlyFolderLeavesThePreviousFileIntact) {
    TempFolder dir;
    const std::string path = dir / "keep.json";
    ASSERT_EQ(savePresetFile(path, Settings{}, "old"), "");
    const std::string before = readFile(path);
    // Readable and searchable by everyone, writable by no one.
    fs::permissions(dir.path, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                  fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
    std::string e;
    {
        const test::AsUnprivilegedUser user;  // root (CI) ignores folder permissions
        EXPECT_EQ(user.error(), "");
        e = savePresetFile(path, awkwardSettings(), "new");
    }
    fs::permissions(dir.path, fs::perms::owner_all);
    EXPECT_TRUE(contains(e, "Permission denied")) << e;
    EXPECT_EQ(readFile(path), before);
    EXPECT_EQ(filesIn(dir.path), std::set<std::string>{"keep.json"});
}

TEST(Presets, InvalidSettingsAreNotSaved) {
    TempFolder dir;
    const std::string path = dir / "keep.json";
    ASSERT_EQ(savePresetFile(path, Settings{}, "old"), "");
    const std::string before = readFile(path);
    Settings bad;
    bad.lights[0].direction = glm::vec3(0.0f);
    std::string e = savePresetFile(path, bad);
    EXPECT_TRUE(contains(e, "lights.0.direction")) << e;
    EXPECT_EQ(readFile(path), before);
}

TEST(Presets, FileErrorsNameTheFile) {
    TempFolder dir;
    PresetLoadResult r = loadPresetFile(dir / "missing.json");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0], dir / "missing.json" + ": no such file");
    EXPECT_FALSE(r.settings);

    r = loadPresetFile(dir.path.string());
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_TRUE(contains(r.errors[0], "is a folder")) << r.errors[0];

    // A syntax error on line 4: the message gives path:line:column.
    const std::string bad = dir / "bad.json";
    writeFile(bad, "{\n  \"schema\": \"shadowlab-preset\",\n  \"schemaVersion\": 1,\n  \"shadow\": {\"depthBias\": 2,}\n}\n");
    r = loadPresetFile(bad);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_TRUE(contains(r.errors[0], bad + ":4:29: invalid JSON: syntax error")) << r.errors[0];
    EXPECT_FALSE(r.settings);

    // 1e400 is no JSON number nlohmann accepts (overflow); it is still reported with its position.
    writeFile(bad, "{\"schema\": \"shadowlab-preset\", \"schemaVersion\": 1,\n \"shadow\": {\"depthBias\": 1e400}}");
    r = loadPresetFile(bad);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_TRUE(contains(r.errors[0], bad + ":2:")) << r.errors[0];
    EXPECT_TRUE(contains(r.errors[0], "1e400")) << r.errors[0];

    writeFile(bad, "");
    r = loadPresetFile(bad);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_TRUE(contains(r.errors[0], bad + ":1:1: invalid JSON")) << r.errors[0];

    // Content errors and warnings are prefixed with the path as well.
    writeFile(bad, R"({"schema": "shadowlab-preset", "schemaVersion": 1, "light": {"ambient": 2}, "extra": 1})");
    r = loadPresetFile(bad);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0], bad + ": light.ambient: 2 is out of range (allowed [0, 1])");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0], bad + ": unknown key 'extra' ignored");
}

TEST(Presets, ShippedPresetsLoadCleanlyAndAreCanonical) {
    const fs::path folder = fs::path(SHADOWLAB_SOURCE_DIR) / "presets";
    std::set<std::string> schema1, schema2;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.path().extension() != ".json") continue;
        const std::string path = entry.path().string();
        SCOPED_TRACE(path);
        PresetLoadResult r = loadPresetFile(path);
        ASSERT_TRUE(r.errors.empty()) << joinLines(r.errors);
        EXPECT_TRUE(r.warnings.empty()) << joinLines(r.warnings);
        ASSERT_TRUE(r.settings);
        EXPECT_EQ(r.name, entry.path().stem().string());
        EXPECT_GT(r.description.size(), 40u);
        const std::string text = readFile(path);
        const int version = json::parse(text).at("schemaVersion").get<int>();
        if (version == 1) {
            // The one-light presets stay schema 1 on purpose (they prove migration): one light, and what it saves
            // as (schema 2) loads back the same settings.
            EXPECT_EQ(r.settings->lights.size(), 1u);
            const std::string saved = presetToText(*r.settings, r.name, r.description, r.scene);
            EXPECT_TRUE(contains(saved, "\"schemaVersion\": 2,"));
            PresetLoadResult again = presetFromText(saved);
            ASSERT_TRUE(again.settings) << joinLines(again.errors);
            EXPECT_TRUE(*again.settings == *r.settings);
            EXPECT_EQ(presetToText(*again.settings, r.name, r.description, r.scene), saved);  // canonical
            schema1.insert(r.name);
        } else {
            // Schema 2 files are written by the tool: the text is exactly what saving what it loads writes.
            EXPECT_EQ(version, kPresetSchemaVersion);
            EXPECT_EQ(presetToText(*r.settings, r.name, r.description, r.scene), text);
            schema2.insert(r.name);
        }
    }
    for (const char* expected : {"default", "acne", "peter-panning", "soft", "pcf-wide"})
        EXPECT_TRUE(schema1.count(expected)) << expected << ".json missing or not schema 1";
    for (const char* expected : {"room", "courtyard"})
        EXPECT_TRUE(schema2.count(expected)) << expected << ".json missing or not schema 2";
}

TEST(Presets, ShippedPresetsShowWhatTheirNamesSay) {
    auto load = [](const std::string& name) {
        PresetLoadResult r = loadPresetFile(std::string(SHADOWLAB_SOURCE_DIR) + "/presets/" + name + ".json");
        EXPECT_TRUE(r.settings) << joinLines(r.errors);
        return r.settings.value_or(Settings{});
    };
    EXPECT_TRUE(load("default") == Settings{});

    Settings acne = load("acne");
    EXPECT_EQ(acne.lights[0].shadow.depthBias, 0.0f);
    EXPECT_EQ(acne.lights[0].shadow.slopeScaledDepthBias, 0.0f);
    EXPECT_EQ(acne.lights[0].shadow.normalOffset, 0.0f);
    EXPECT_EQ(acne.lights[0].shadow.cullMode, CullMode::None);
    EXPECT_EQ(acne.filter.kind, FilterKind::Point);

    // Over a world unit of constant bias over a 29-unit depth range (D32F step 2^-24 for depths in [0.5, 1)).
    Settings pp = load("peter-panning");
    const double worldBias = pp.lights[0].shadow.depthBias * std::ldexp(1.0, -24) * 29.0;
    EXPECT_GT(worldBias, 1.0);
    EXPECT_EQ(pp.lights[0].shadow.cullMode, CullMode::Front);
    EXPECT_GE(pp.lights[0].shadow.normalOffset, 4.0f);

    Settings soft = load("soft");
    EXPECT_EQ(soft.filter.kind, FilterKind::Poisson);
    EXPECT_EQ(soft.filter.poissonRadius, 3.0f);
    EXPECT_GE(soft.lights[0].shadow.slopeScaledDepthBias, soft.filter.poissonRadius + 1.0f);

    Settings wide = load("pcf-wide");
    EXPECT_EQ(wide.filter.kind, FilterKind::Pcf);
    EXPECT_EQ(wide.filter.kernel, 9);
    EXPECT_GE(wide.lights[0].shadow.slopeScaledDepthBias, static_cast<float>(wide.filter.kernel / 2) + 1.0f);
}

// presets/room.json and presets/courtyard.json list their scene's lights themselves (useSceneLights stays off), so
// they light the scene the same way its SceneLights do: same kinds, order, positions, aims, cones, ranges, colours.
TEST(Presets, LightPresetsHoldTheirScenesLights) {
    for (const std::string name : {"room", "courtyard"}) {
        SCOPED_TRACE(name);
        const PresetLoadResult r = loadPresetFile(std::string(SHADOWLAB_SOURCE_DIR) + "/presets/" + name + ".json");
        ASSERT_TRUE(r.settings) << joinLines(r.errors);
        EXPECT_EQ(r.scene, "builtin:" + name);
        EXPECT_FALSE(r.settings->useSceneLights);
        const std::optional<Scene> scene = makeBuiltinScene(name);
        ASSERT_TRUE(scene);
        Settings fromScene;
        fromScene.useSceneLights = true;
        const std::vector<LightSettings> expected = effectiveLights(fromScene, *scene);
        const std::vector<LightSettings>& lights = r.settings->lights;
        ASSERT_EQ(lights.size(), expected.size());
        for (std::size_t i = 0; i < lights.size(); ++i) {
            SCOPED_TRACE("light " + std::to_string(i) + " (" + scene->lights[i].name + ")");
            const LightSettings &got = lights[i], &want = expected[i];
            EXPECT_EQ(got.type, want.type);
            EXPECT_TRUE(got.enabled && got.castsShadows);
            if (want.type != LightType::Point)  // the preset may write the aim unnormalized, e.g. [1, -1, 1]
                EXPECT_GT(glm::dot(glm::normalize(got.direction), glm::normalize(want.direction)), 1.0f - 1e-6f);
            if (want.type != LightType::Directional) {
                EXPECT_EQ(got.position, want.position);
                EXPECT_EQ(got.range, want.range);
            }
            if (want.type == LightType::Spot) EXPECT_NEAR(got.spotConeDeg, want.spotConeDeg, 1e-4f);
            EXPECT_EQ(got.color, want.color);
            EXPECT_EQ(got.intensity, want.intensity);
            // Tuned, not left at the defaults' 0.5-texel normal offset (acne 0.13 % for courtyard's spot-hall).
            EXPECT_EQ(got.shadow.normalOffset, 1.0f);
        }
    }
}
