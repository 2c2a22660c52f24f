#include "editor/accuracy_state.h"

#include "settings/settings_fields.h"

namespace shadowlab::editor {

namespace {

bool sameCamera(const Camera& a, const Camera& b) {
    return a.position == b.position && a.target == b.target && a.fovYDeg == b.fovYDeg && a.nearPlane == b.nearPlane &&
           a.farPlane == b.farPlane;
}

Settings withoutView(Settings s) {
    s.view = ViewMode::Lit;
    return s;
}

}  // namespace

bool sameReferenceView(const AccuracyViewKey& a, const AccuracyViewKey& b) {
    return a.scene == b.scene && a.width == b.width && a.height == b.height && a.light == b.light &&
           sameCamera(a.camera, b.camera);
}

bool AccuracyViewKey::operator==(const AccuracyViewKey& other) const {
    return scene == other.scene && width == other.width && height == other.height && light == other.light &&
           sameCamera(camera, other.camera) && withoutView(settings) == withoutView(other.settings);
}

std::string staleReason(const AccuracyViewKey& measured, const AccuracyViewKey& now) {
    if (measured.scene != now.scene) return "another scene is open";
    std::string reason;
    auto add = [&](const std::string& part) { reason += (reason.empty() ? "" : "; ") + part; };
    std::string keys;
    int changedKeys = 0;
    for (const std::string& key : diffSettings(measured.settings, now.settings).keys) {
        if (key == "view") continue;
        if (++changedKeys <= 3) keys += (keys.empty() ? "" : ", ") + key;
    }
    if (changedKeys > 3) keys += " and " + std::to_string(changedKeys - 3) + " more";
    if (!keys.empty()) add(keys + " changed");
    if (measured.light != now.light)
        add("light " + std::to_string(now.light) + " is selected, the numbers are light " + std::to_string(measured.light) + "'s");
    if (!sameCamera(measured.camera, now.camera)) add("the camera moved");
    if (measured.width != now.width || measured.height != now.height)
        add("the view is " + std::to_string(now.width) + "x" + std::to_string(now.height) + ", measured at " +
            std::to_string(measured.width) + "x" + std::to_string(measured.height));
    return reason;
}

}  // namespace shadowlab::editor
