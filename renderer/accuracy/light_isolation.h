#pragma once
// Per-light accuracy by isolation: the shadow factor of light i in a many-light frame is computed exactly as in a
// frame holding only light i (each light has its own shadow views, projection and bias), so light i is measured by
// measuring a Settings whose `lights` is just the effective light i (light/scene_lights.h resolves useSceneLights).
// A light that is disabled or has castsShadows off casts no shadow: there is nothing to measure for it.
#include "scene/scene.h"
#include "settings/settings.h"

#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

// Why light i of the effective lights cannot be measured ("" when it can): no such light, disabled, or castsShadows
// off. The message names the key (e.g. "lights.5: no such light (the settings have 2 lights: 0..1)").
std::string unmeasurableReason(const Settings& settings, const Scene& scene, std::size_t index);

// The effective lights' indices that cast shadows (enabled and castsShadows), in order.
std::vector<std::size_t> castingLights(const Settings& settings, const Scene& scene);

// `settings` holding only the effective light i (useSceneLights off); nullopt with `error` when it cannot be measured.
std::optional<Settings> isolateLight(const Settings& settings, const Scene& scene, std::size_t index,
                                     std::string& error);

// The tools that describe one light (the accuracy meter, the bias tuner, the pixel probe) take settings holding
// exactly that light: "" when `settings` has one effective light, else why not, naming `tool`. They never fall back
// to light 0 of several: the caller says which light (isolateLight), and the tool's report names it.
std::string singleLightError(const Settings& settings, const Scene& scene, const std::string& tool);

// A message about the isolated settings (whose only light is lights.0) as it reads for light `index` of the
// caller's: "lights.0.range: ..." -> "lights.3.range: ...", anything else prefixed "lights.3: " (never twice).
std::string messageForLight(const std::string& message, std::size_t index);

// Writes a tuned shadow map (bias, cull mode) back into light i of `settings`. With useSceneLights the scene's
// light i takes its tuning from lights[min(i, last)], so the list is first padded with copies of its last entry:
// the other scene lights keep the tuning they had.
void setLightShadow(Settings& settings, std::size_t index, const ShadowMapSettings& shadow);

}  // namespace shadowlab
