#include "settings/settings.h"

#include "settings/settings_fields.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace shadowlab {

std::vector<std::string> Settings::validate() const {
    std::vector<std::string> problems;

    // Per-field ranges: a value is valid exactly when its own set() would accept it again, so the table stays the
    // only place that knows a range. The scratch copy keeps this const.
    for (const SettingsField& field : settingsFields()) {
        Settings scratch = *this;
        if (std::string error = field.set(scratch, field.get(*this)); !error.empty()) problems.push_back(error);
    }

    // Rules that involve more than one field.
    if (!projection.autoFit && !(projection.nearPlane < projection.farPlane)) {
        problems.push_back("projection.near: " + describeJsonValue(findSettingsField("projection.near")->get(*this)) +
                           " is not less than projection.far " +
                           describeJsonValue(findSettingsField("projection.far")->get(*this)) + " (allowed near < far)");
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
