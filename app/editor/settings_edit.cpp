#include "editor/settings_edit.h"

#include "settings/settings_fields.h"

namespace shadowlab::editor {

std::string applyEdit(Settings& settings, std::string_view key, const nlohmann::json& value, const EditLimits& limits) {
    const SettingsField* field = findSettingsField(key);
    if (!field) return std::string(key) + ": not a setting";
    // The key table allows up to 32768; this GPU may allow less. Checked here so the previous map is kept.
    if (key == "shadow.resolution" && limits.maxTextureSize > 0 && value.is_number() &&
        value.get<double>() > limits.maxTextureSize)
        return "shadow.resolution: " + describeJsonValue(value) + " is above this GPU's GL_MAX_TEXTURE_SIZE " +
               std::to_string(limits.maxTextureSize) + "; keeping the previous map";
    Settings candidate = settings;
    if (std::string error = field->set(candidate, value); !error.empty()) return error;
    if (std::vector<std::string> problems = candidate.validate(); !problems.empty()) return problems.front();
    settings = candidate;
    return {};
}

}  // namespace shadowlab::editor
