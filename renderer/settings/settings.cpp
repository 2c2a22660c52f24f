#include "settings/settings.h"

#include "settings/settings_fields.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace shadowlab {

std::vector<std::string> Settings::validate() const {
    std::vector<std::string> problems;

    // Per-field ranges: a value is valid exactly when its own set() would accept it again, so the table stays the
    // only place that knows a range. The scratch copy keeps this const.
    if (lights.size() > kMaxLights)
        problems.push_back("lights: " + std::to_string(lights.size()) + " lights (allowed at most " +
                           std::to_string(kMaxLights) + ")");
    for (const SettingsField* field : settingsFieldsOf(*this)) {
        Settings scratch = *this;
        if (std::string error = field->set(scratch, field->get(*this)); !error.empty()) problems.push_back(error);
    }

    // Rules that involve more than one field.
    for (std::size_t i = 0; i < lights.size() && i < kMaxLights; ++i) {
        const ProjectionSettings& projection = lights[i].projection;
        if (projection.autoFit || projection.nearPlane < projection.farPlane) continue;
        const std::string prefix = "lights." + std::to_string(i) + ".projection.";
        problems.push_back(prefix + "near: " + describeJsonValue(findSettingsField(prefix + "near")->get(*this)) +
                           " is not less than " + prefix + "far " +
                           describeJsonValue(findSettingsField(prefix + "far")->get(*this)) + " (allowed near < far)");
    }
    // A directional light's size is an angle: the key's range is a radius's.
    for (std::size_t i = 0; i < lights.size() && i < kMaxLights; ++i) {
        if (lights[i].type != LightType::Directional || !(lights[i].size > kMaxAngularDiameterDeg)) continue;
        const std::string key = "lights." + std::to_string(i) + ".size";
        problems.push_back(key + ": " + describeJsonValue(findSettingsField(key)->get(*this)) +
                           " degrees is too wide for a directional light's angular diameter (allowed [0, " +
                           std::to_string(int(kMaxAngularDiameterDeg)) +
                           "] for a directional light; a spot or point light's radius up to 1e6)");
    }
    if (!camera.autoFrame) {
        // glm::lookAt(eye == center) is all NaN (HARD_CASES 14).
        const glm::dvec3 d = camera.target - camera.position;
        if (!(glm::length(d) > 1e-6))
            problems.push_back("camera.target: equals camera.position, the camera has no view direction (allowed "
                               "a target at least 1e-6 from the position)");
    }
    return problems;
}

}  // namespace shadowlab
