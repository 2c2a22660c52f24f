#include "light/scene_lights.h"

#include <glm/trigonometric.hpp>

#include <algorithm>

namespace shadowlab {

namespace {

LightSettings fromScene(const SceneLight& sl, const LightSettings& tuning) {
    LightSettings light = tuning;  // shadow, projection, enabled, castsShadows
    switch (sl.type) {
        case SceneLightType::Directional: light.type = LightType::Directional; break;
        case SceneLightType::Spot: light.type = LightType::Spot; break;
        case SceneLightType::Point: light.type = LightType::Point; break;
    }
    light.direction = sl.direction;
    light.position = sl.position;
    light.range = std::clamp(sl.range, 0.0f, 1e7f);
    light.spotConeDeg = std::clamp(float(glm::degrees(2.0 * double(sl.outerConeRad))), 1.0f, 170.0f);
    // glTF's units (lux, candela) have no meaning in this tool's unlit-by-units shading: kept as given, within the
    // key's range, so relative strengths between lights survive.
    light.intensity = std::clamp(sl.intensity, 0.0f, 100.0f);
    light.color = glm::clamp(sl.color, glm::vec3(0.0f), glm::vec3(100.0f));
    return light;
}

}  // namespace

std::vector<LightSettings> effectiveLights(const Settings& settings, const Scene& scene) {
    if (!settings.useSceneLights || scene.lights.empty()) return settings.lights;
    std::vector<LightSettings> lights;
    const LightSettings fallback{};
    for (std::size_t i = 0; i < scene.lights.size() && i < kMaxLights; ++i) {
        const LightSettings& tuning = settings.lights.empty() ? fallback
                                                              : settings.lights[std::min(i, settings.lights.size() - 1)];
        lights.push_back(fromScene(scene.lights[i], tuning));
    }
    return lights;
}

Settings withEffectiveLights(const Settings& settings, const Scene& scene) {
    Settings effective = settings;
    effective.lights = effectiveLights(settings, scene);
    effective.useSceneLights = false;
    return effective;
}

std::string describeLightSource(const Settings& settings, const Scene& scene) {
    const std::size_t sceneLights = scene.lights.size();
    auto names = [&] {
        std::string out;
        for (std::size_t i = 0; i < sceneLights && i < 4; ++i)
            out += (i ? ", '" : "'") + (scene.lights[i].name.empty() ? std::string("unnamed") : scene.lights[i].name) + "'";
        return out + (sceneLights > 4 ? ", ..." : "");
    };
    if (settings.useSceneLights && sceneLights > 0) {
        std::string text = "the scene's " + std::to_string(std::min(sceneLights, kMaxLights)) + " light" +
                           (sceneLights == 1 ? "" : "s") + " (" + names() + ")";
        if (sceneLights > kMaxLights) text += "; the first " + std::to_string(kMaxLights) + " of " + std::to_string(sceneLights);
        return text;
    }
    const std::string own = std::to_string(settings.lights.size()) + " light" + (settings.lights.size() == 1 ? "" : "s");
    if (settings.useSceneLights) return "the settings' " + own + " (the scene has no glTF light)";
    if (sceneLights > 0)
        return "the settings' " + own + " (the scene has " + std::to_string(sceneLights) + " glTF light" +
               (sceneLights == 1 ? "" : "s") + ": useSceneLights=true uses them)";
    return "the settings' " + own;
}

}  // namespace shadowlab
