#pragma once
// The one table of tunables. Every Settings field appears here once, under its dotted preset key ("filter.kind",
// and per light "lights.2.shadow.depthBias"); JSON load, JSON save, `--set key=value`, Settings::validate() and the
// editor's sliders all go through it, so a key, its range and its error messages live in exactly one place.
// Each field also says what a change of it makes stale (SettingsField::invalidates): the shadow planner's reasons,
// the main pass's variant key and the editor's redraw decision derive from those tags, not from hand lists.
// The schema-1 keys of the one-light presets ("shadow.depthBias", "light.type", "projection.near", "light.ambient",
// "light.useSceneLight") stay valid as aliases (of light 0 where they name a light's field).
#include "settings/settings.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

enum class SettingsFieldKind { Bool, Int, Float, Enum, Vec3, String, StringList };

// What a change of a field makes stale (bit flags). Every change redraws the main pass; these say what else.
enum Invalidates : unsigned {
    kInvalidatesNothingElse = 0,
    kInvalidatesShadowView = 1u << 0,  // the light's shadow views (its map contents or its light space)
    kInvalidatesSampler = 1u << 1,     // sampler state of the maps
    kInvalidatesVariant = 1u << 2,     // the main pass's shader variant (its #defines)
    kInvalidatesCamera = 1u << 3,      // the camera: which views the camera can see
};

struct SettingsField {
    std::string key;          // dotted preset key, e.g. "shadow.depthBias"; the part before the dot is the JSON group
    std::string description;  // one line, for --help, tooltips and docs
    std::string allowed;      // human text of what set() accepts, e.g. "[0, 1]" or "one of d16, d24, d32f"
    std::string unit;         // what a number counts, e.g. "world units", "degrees"; "" for names, flags and ratios
    SettingsFieldKind kind = SettingsFieldKind::Float;
    double min = 0.0;                  // Int / Float: inclusive range (also a slider's range)
    double max = 0.0;                  // StringList: the most entries
    std::vector<std::string> choices;  // Enum: the names, in enum order
    std::vector<int> intChoices;       // Int restricted to a set (filter.kernel); empty = any integer in [min, max]
    unsigned invalidates = kInvalidatesNothingElse;  // Invalidates flags
    int light = -1;           // the light this field belongs to (an alias of a schema-1 key: 0); -1 = global
    std::string aliasOf;      // schema-1 alias: the key it stands for ("lights.0.shadow.depthBias"); "" otherwise

    // The current value as JSON (floats as the shortest decimal that reads back to the same float).
    std::function<nlohmann::json(const Settings&)> get;
    // Checks and stores a value. Returns "" on success; otherwise "key: problem (allowed ...)" naming the bad
    // value, and Settings is left untouched.
    std::function<std::string(Settings&, const nlohmann::json&)> set;

    // The key within its light: "shadow.depthBias" for "lights.2.shadow.depthBias", "type" for "lights.0.type";
    // the whole key for a global field.
    std::string_view lightKey() const;
    // Of lightKey(): "shadow" for "shadow.depthBias", "" for "view" or a light's "type".
    std::string_view group() const;
    // Of lightKey(): "depthBias" for "shadow.depthBias", "view" for "view".
    std::string_view name() const;
    // "lights.#.shadow.depthBias" for a light's field (any index), the key itself for a global one.
    std::string pattern() const;
};

// The global fields (ambient, useSceneLights, sampler, filter, camera, casters, animation, view), in preset order.
const std::vector<SettingsField>& globalSettingsFields();

// Light `light`'s fields ("lights.<light>.*"), in preset order; light < kMaxLights. Setting a field of light
// lights.size() appends a default light first (so `--set lights.1.type=point` adds a second light); a higher index is
// refused, naming how many lights there are.
const std::vector<SettingsField>& lightSettingsFields(std::size_t light);

// Every field the settings have: the global ones, then each light's. (What validate, presets and diffs walk.)
std::vector<const SettingsField*> settingsFieldsOf(const Settings& settings);

// The keys as `shadowlab keys` and docs list them: global fields, then light fields once as "lights.#.*".
std::vector<const SettingsField*> settingsKeyListing();

// The schema-1 keys that stand for a newer key ("shadow.depthBias" -> "lights.0.shadow.depthBias").
const std::vector<SettingsField>& schema1Aliases();

// nullptr when the key is unknown. Exact, case-sensitive match of a global key, "lights.<n>.<key>" with n <
// kMaxLights, or a schema-1 alias (whose messages name the alias as typed).
const SettingsField* findSettingsField(std::string_view key);

// The keys whose values differ between a and b (lights present in only one of them count as their "lights.<n>"),
// with the union of what those changes invalidate.
struct SettingsDiff {
    std::vector<std::string> keys;
    unsigned invalidates = kInvalidatesNothingElse;
    bool empty() const { return keys.empty(); }
};
// `tags`: only the fields carrying one of these Invalidates flags (kEveryField: all of them).
inline constexpr unsigned kEveryField = ~0u;
SettingsDiff diffSettings(const Settings& a, const Settings& b, unsigned tags = kEveryField);
// As diffSettings, for the global fields only (ambient, filter, casters, ...).
SettingsDiff diffGlobals(const Settings& a, const Settings& b, unsigned tags = kEveryField);
// As diffSettings, for one light only (a light's own fields, no global ones), keys within the light ("type").
SettingsDiff diffLight(const LightSettings& a, const LightSettings& b, unsigned tags = kEveryField);

// Keys close to an unknown one (typos, missing group, wrong case), best first; empty when nothing is close or the
// key is longer than kMaxSuggestedKeyLength (no key is near it, and the search costs length squared).
inline constexpr std::size_t kMaxSuggestedKeyLength = 64;
std::vector<std::string> similarSettingsKeys(std::string_view key);

// `--set key=value`. The value is read as JSON when it parses (numbers, true/false, [1,2,3], "quoted"), otherwise
// as a bare string (so `filter.kind=poisson` works). Returns "" on success, otherwise an error naming the key; on
// error Settings is untouched.
std::string applySettingOverride(Settings& settings, std::string_view keyEqualsValue);

// A JSON value as a user would type it, for messages (NaN and infinities included, long values shortened).
// Bounded in time and depth whatever the value; bytes that are not UTF-8 print as U+FFFD.
std::string describeJsonValue(const nlohmann::json& value);

// A light type as presets spell it ("directional", "spot", "point"), from the key table: one name everywhere.
std::string lightTypeName(LightType type);

// A key as a message shows it: at most 60 bytes (then "... (N bytes)"), escaped, never invalid UTF-8.
std::string describeKey(std::string_view key);

}  // namespace shadowlab
