#include "accuracy/light_isolation.h"

#include "light/scene_lights.h"

namespace shadowlab {

std::string unmeasurableReason(const Settings& settings, const Scene& scene, std::size_t index) {
    const std::vector<LightSettings> lights = effectiveLights(settings, scene);
    const std::string key = "lights." + std::to_string(index);
    if (index >= lights.size()) {
        const std::string source = settings.useSceneLights && !scene.lights.empty() ? "the scene has " : "the settings have ";
        if (lights.empty()) return key + ": no such light (" + source + "no lights)";
        return key + ": no such light (" + source + std::to_string(lights.size()) + " light" +
               (lights.size() == 1 ? "" : "s") + ": 0.." + std::to_string(lights.size() - 1) + ")";
    }
    if (!lights[index].enabled) return key + ".enabled is false: the light is off, nothing to measure";
    if (!lights[index].castsShadows) return key + ".castsShadows is false: it casts no shadow, nothing to measure";
    return "";
}

std::vector<std::size_t> castingLights(const Settings& settings, const Scene& scene) {
    const std::vector<LightSettings> lights = effectiveLights(settings, scene);
    std::vector<std::size_t> casting;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (lights[i].enabled && lights[i].castsShadows) casting.push_back(i);
    return casting;
}

std::optional<Settings> isolateLight(const Settings& settings, const Scene& scene, std::size_t index,
                                     std::string& error) {
    error = unmeasurableReason(settings, scene, index);
    if (!error.empty()) return std::nullopt;
    Settings one = withEffectiveLights(settings, scene);
    one.lights = {one.lights[index]};
    return one;
}

std::string singleLightError(const Settings& settings, const Scene& scene, const std::string& tool) {
    const std::size_t count = effectiveLights(settings, scene).size();
    if (count == 1) return "";
    if (count == 0) return tool + ": there is no light (the settings have no lights)";
    return tool + " describes one light, and these settings have " + std::to_string(count) +
           " lights: choose one (the CLI's --light N, the editor's selected light)";
}

std::string messageForLight(const std::string& message, std::size_t index) {
    const std::string key = "lights." + std::to_string(index);
    const std::string isolated = "lights.0";
    if (message.rfind(isolated, 0) == 0 && message.size() > isolated.size() &&
        (message[isolated.size()] == '.' || message[isolated.size()] == ':'))
        return key + message.substr(isolated.size());
    if (message.rfind(key + ":", 0) == 0 || message.rfind(key + ".", 0) == 0) return message;
    return key + ": " + message;
}

void setLightShadow(Settings& settings, std::size_t index, const ShadowMapSettings& shadow) {
    if (settings.lights.empty()) settings.lights.emplace_back();
    while (settings.lights.size() <= index) settings.lights.push_back(settings.lights.back());
    settings.lights[index].shadow = shadow;
}

}  // namespace shadowlab
