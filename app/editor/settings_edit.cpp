#include "editor/settings_edit.h"

#include "settings/settings_fields.h"

#include <algorithm>

namespace shadowlab::editor {

std::string applyEdit(Settings& settings, std::string_view key, const nlohmann::json& value, const EditLimits& limits) {
    const SettingsField* field = findSettingsField(key);
    if (!field) return std::string(key) + ": not a setting";
    // The key table allows up to 32768; this GPU may allow less. Checked here so the previous map is kept.
    if (field->lightKey() == "shadow.resolution" && limits.maxTextureSize > 0 && value.is_number() &&
        value.get<double>() > limits.maxTextureSize)
        return std::string(key) + ": " + describeJsonValue(value) + " is above this GPU's GL_MAX_TEXTURE_SIZE " +
               std::to_string(limits.maxTextureSize) + "; keeping the previous map";
    Settings candidate = settings;
    if (std::string error = field->set(candidate, value); !error.empty()) return error;
    if (std::vector<std::string> problems = candidate.validate(); !problems.empty()) return problems.front();
    settings = candidate;
    return {};
}

namespace {

std::string validated(Settings& settings, Settings candidate) {
    if (std::vector<std::string> problems = candidate.validate(); !problems.empty()) return problems.front();
    settings = std::move(candidate);
    return {};
}

std::string noSuchLight(const Settings& settings, std::size_t index) {
    return "lights." + std::to_string(index) + ": no such light (there are " + std::to_string(settings.lights.size()) +
           ")";
}

}  // namespace

std::string removeLight(Settings& settings, std::size_t index) {
    if (index >= settings.lights.size()) return noSuchLight(settings, index);
    Settings candidate = settings;
    candidate.lights.erase(candidate.lights.begin() + std::ptrdiff_t(index));
    return validated(settings, std::move(candidate));
}

std::string duplicateLight(Settings& settings, std::size_t index) {
    if (index >= settings.lights.size()) return noSuchLight(settings, index);
    if (settings.lights.size() >= kMaxLights)
        return "lights: already " + std::to_string(settings.lights.size()) + " lights (allowed at most " +
               std::to_string(kMaxLights) + ")";
    Settings candidate = settings;
    candidate.lights.push_back(settings.lights[index]);
    return validated(settings, std::move(candidate));
}

std::string manualFromFitted(Settings& settings, std::size_t index, const LightSpace& fitted) {
    if (index >= settings.lights.size()) return noSuchLight(settings, index);
    Settings candidate = settings;
    ProjectionSettings& projection = candidate.lights[index].projection;
    const std::string prefix = "lights." + std::to_string(index) + ".projection.";
    // The key table's range of each value: the one place it is stated.
    auto inRange = [&](const char* name, double value) {
        const SettingsField* field = findSettingsField(prefix + name);
        return float(field ? std::clamp(value, field->min, field->max) : value);
    };
    projection.autoFit = false;
    if (!fitted.perspective) projection.orthoSize = inRange("orthoSize", fitted.orthoSize);
    projection.nearPlane = inRange("near", fitted.nearPlane);
    projection.farPlane = inRange("far", fitted.farPlane);
    return validated(settings, std::move(candidate));
}

}  // namespace shadowlab::editor
