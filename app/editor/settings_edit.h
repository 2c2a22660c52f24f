#pragma once
// The one way the editor changes Settings: the key table's SettingsField::set, then Settings::validate() on the
// result. A refusal leaves the settings exactly as they were and says why, naming the key, like presets and --set.
#include "light/light_space.h"
#include "settings/settings.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace shadowlab::editor {

struct EditLimits {
    int maxTextureSize = 0;  // GL_MAX_TEXTURE_SIZE of the editor's context; 0 = unknown (no extra cap)
};

// Applies `value` to `key` in `settings`. Returns "" when applied, else the refusal (settings untouched).
std::string applyEdit(Settings& settings, std::string_view key, const nlohmann::json& value, const EditLimits& limits);

// The Lights panel's list changes that are not one key: removing light `index` (the later ones move up) and
// appending a copy of it. Each validates the result; "" when done, else why (settings untouched). Zero lights are
// allowed: the scene is then lit by the ambient term only.
std::string removeLight(Settings& settings, std::size_t index);
std::string duplicateLight(Settings& settings, std::size_t index);

// Light `index`'s projection made manual, starting from the volume auto-fit chose (`fitted`, one of its views), so
// turning auto-fit off does not jump. Each value is brought into its key's range first: a directional fit starts at
// near 0, below the key's least near plane, and the result must stay editable. "" when applied, else why.
std::string manualFromFitted(Settings& settings, std::size_t index, const LightSpace& fitted);

}  // namespace shadowlab::editor
