#pragma once
// Presets: a Settings as a schema-versioned JSON object, nested by the dotted keys of settings_fields.h:
//   {"schema": "shadowlab-preset", "schemaVersion": 2, "name": "...", "description": "...", "scene": "...",
//    "ambient": 0.15, "useSceneLights": false,
//    "lights": [{"type": "directional", "direction": [...], ..., "shadow": {"resolution": 2048, ...},
//                "projection": {...}}, ...],
//    "sampler": {...}, "filter": {...}, "camera": {...}, "view": "lit"}
// Schema 1 (one light: "shadow", "light", "projection" groups at the top) loads as a one-light scene and is saved
// as schema 2.
// "scene" (optional; older presets have none) is the scene the preset was tuned on, as given to --scene or opened in
// the editor; the camera group then holds the camera that was used there (see preset_scene.h).
// Floats are written as the shortest decimal that reads back to the same float, so save -> load is exact.
#include "image/png_text.h"
#include "settings/settings.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

inline constexpr const char* kPresetSchema = "shadowlab-preset";
inline constexpr int kPresetSchemaVersion = 2;  // 2: a list of lights; 1 (one light) still loads

nlohmann::json presetToJson(const Settings& settings, const std::string& name = {},
                            const std::string& description = {}, const std::string& scene = {});

// The preset as file text: keys in Settings order (not alphabetical), [x, y, z] on one line, trailing newline.
std::string presetToText(const Settings& settings, const std::string& name = {}, const std::string& description = {},
                         const std::string& scene = {});

struct PresetLoadResult {
    std::optional<Settings> settings;   // set only when errors is empty: nothing is ever partially applied
    std::vector<std::string> errors;    // "key: problem (allowed ...)"; from files prefixed with the path
    std::vector<std::string> warnings;  // unknown keys (ignored)
    std::string name, description;
    std::string scene;  // the scene it was tuned on; "" for presets that record none
};

// Keys absent from the preset keep base's values. Unknown keys are warnings; a wrong type, a value out of range,
// a missing or newer schemaVersion, or settings that fail Settings::validate() are errors.
PresetLoadResult presetFromJson(const nlohmann::json& preset, const Settings& base = Settings{});

// As presetFromJson, from JSON text: errors for text nesting deeper than kMaxJsonNesting and for JSON syntax
// ("line:column: invalid JSON: ...").
PresetLoadResult presetFromText(const std::string& text, const Settings& base = Settings{});

inline constexpr std::size_t kMaxPresetBytes = 16u << 20;

// The PNG text chunk a screenshot carries its preset in (the preset's JSON, its "scene" included).
inline constexpr const char* kPresetPngKeyword = "shadowlab.preset";
// An A/B screenshot's other side (A; the picture's own preset, kPresetPngKeyword, is B's, the one being edited).
inline constexpr const char* kPresetAPngKeyword = "shadowlab.presetA";
PngText presetPngText(const Settings& settings, const std::string& scene);

// As presetFromText, plus file errors (missing, unreadable, JSON syntax error at path:line:column). A PNG is read
// through its kPresetPngKeyword chunk (a screenshot brings its preset back); one without it is an error saying so.
PresetLoadResult loadPresetFile(const std::string& path, const Settings& base = Settings{});

// Writes atomically: a temporary file in the same folder, fsync, rename over path. Any failure leaves the previous
// file as it was and removes the temporary. Refuses settings that fail validate(). Returns "" or an error message.
std::string savePresetFile(const std::string& path, const Settings& settings, const std::string& name = {},
                           const std::string& description = {}, const std::string& scene = {});

}  // namespace shadowlab
