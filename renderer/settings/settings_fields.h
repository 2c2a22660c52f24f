#pragma once
// The one table of tunables. Every Settings field appears here once, under its dotted preset key
// ("shadow.depthBias"); JSON load, JSON save, `--set key=value`, Settings::validate() and the editor's
// sliders all go through it, so a key, its range and its error messages live in exactly one place.
#include "settings/settings.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

enum class SettingsFieldKind { Bool, Int, Float, Enum, Vec3 };

struct SettingsField {
    std::string key;          // dotted preset key, e.g. "shadow.depthBias"; the part before the dot is the JSON group
    std::string description;  // one line, for --help, tooltips and docs
    std::string allowed;      // human text of what set() accepts, e.g. "[0, 1]" or "one of d16, d24, d32f"
    SettingsFieldKind kind = SettingsFieldKind::Float;
    double min = 0.0;                  // Int / Float: inclusive range (also a slider's range)
    double max = 0.0;
    std::vector<std::string> choices;  // Enum: the names, in enum order
    std::vector<int> intChoices;       // Int restricted to a set (filter.kernel); empty = any integer in [min, max]

    // The current value as JSON (floats as the shortest decimal that reads back to the same float).
    std::function<nlohmann::json(const Settings&)> get;
    // Checks and stores a value. Returns "" on success; otherwise "key: problem (allowed ...)" naming the bad
    // value, and Settings is left untouched.
    std::function<std::string(Settings&, const nlohmann::json&)> set;

    // "shadow" for "shadow.depthBias", "" for "view".
    std::string_view group() const;
    // "depthBias" for "shadow.depthBias", "view" for "view".
    std::string_view name() const;
};

// All fields, in Settings' declaration order (which is also the order presets are written in).
const std::vector<SettingsField>& settingsFields();

// nullptr when the key is unknown. Exact, case-sensitive match.
const SettingsField* findSettingsField(std::string_view key);

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

// A key as a message shows it: at most 60 bytes (then "... (N bytes)"), escaped, never invalid UTF-8.
std::string describeKey(std::string_view key);

}  // namespace shadowlab
