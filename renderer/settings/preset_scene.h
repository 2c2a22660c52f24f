#pragma once
// The framing rule for a preset shown on a scene: a preset records the scene it was tuned on and the camera used
// there. On that scene its camera comes back as saved; on any other scene the saved position means nothing, so the
// camera auto-frames the new scene (the fov is kept) and the caller says so.
#include "settings/settings.h"

#include <string>

namespace shadowlab {

// True when both name the same scene: equal specs, or two paths to one file. "" (no scene recorded) matches any.
bool samePresetScene(const std::string& presetScene, const std::string& sceneSpec);

// Applies the rule to `settings` (camera.autoFrame set on another scene). Returns the note to show, "" when the
// preset records no scene or this one.
std::string adaptPresetToScene(Settings& settings, const std::string& presetScene, const std::string& sceneSpec);

}  // namespace shadowlab
