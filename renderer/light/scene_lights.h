#pragma once
// The lights a frame uses: the settings' list, or with useSceneLights the scene's glTF lights (KHR_lights_punctual:
// directional, spot and point, with glTF's range, colour and intensity). A scene light takes its shadow and
// projection settings (and enabled / castsShadows) from the settings' light at its index, or the last one, so
// tuning lights.0.shadow.* tunes a one-light glTF scene.
#include "scene/scene.h"
#include "settings/settings.h"

#include <string>
#include <vector>

namespace shadowlab {

std::vector<LightSettings> effectiveLights(const Settings& settings, const Scene& scene);

// `settings` with `lights` replaced by the effective ones and useSceneLights off: what every pass works from.
Settings withEffectiveLights(const Settings& settings, const Scene& scene);

// Which lights a frame uses, in words, e.g. "the scene's 3 lights ('Sun', 'Lamp', 'Torch')" (reports, the editor).
std::string describeLightSource(const Settings& settings, const Scene& scene);

}  // namespace shadowlab
