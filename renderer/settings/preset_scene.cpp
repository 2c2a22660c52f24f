#include "settings/preset_scene.h"

#include <filesystem>

namespace shadowlab {

bool samePresetScene(const std::string& presetScene, const std::string& sceneSpec) {
    if (presetScene.empty() || presetScene == sceneSpec) return true;
    std::error_code ec;
    return std::filesystem::equivalent(presetScene, sceneSpec, ec) && !ec;
}

std::string adaptPresetToScene(Settings& settings, const std::string& presetScene, const std::string& sceneSpec) {
    if (samePresetScene(presetScene, sceneSpec)) return {};
    std::string note = "the preset was tuned on " + presetScene + ", shown here on " + sceneSpec;
    if (!settings.camera.autoFrame || settings.camera.sceneCamera >= 0) {
        settings.camera.autoFrame = true;
        settings.camera.sceneCamera = -1;  // a camera of that file, not of this one
        note += ": its camera is for that scene, so the view is auto-framed";
    }
    return note;
}

}  // namespace shadowlab
