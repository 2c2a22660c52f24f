#include "scene/gltf_lights.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace shadowlab::gltf {

namespace {
// As the light.position key allows (HARD_CASES 3: beyond this a float position cannot place a light volume).
constexpr double kMaxLightPosition = 1e7;
}  // namespace

std::optional<SceneLight> importLight(const tg::Model& model, int nodeIndex, const glm::dmat4& world,
                                      const Warn& warn) {
    const tg::Node& node = model.nodes[std::size_t(nodeIndex)];
    const auto it = node.extensions.find("KHR_lights_punctual");
    if (it == node.extensions.end()) return std::nullopt;
    const tg::Value& ext = it->second;
    const int li = ext.IsObject() && ext.Has("light") && ext.Get("light").IsNumber() ? ext.Get("light").GetNumberAsInt() : -1;
    if (li < 0 || li >= int(model.lights.size())) {
        warn("node " + str(nodeIndex) + ": KHR_lights_punctual refers to a light that does not exist; ignored");
        return std::nullopt;
    }
    const tg::Light& gl = model.lights[std::size_t(li)];
    SceneLight light;
    light.name = gl.name.empty() ? "light " + str(li) : gl.name;
    if (gl.type == "directional")
        light.type = SceneLightType::Directional;
    else if (gl.type == "spot")
        light.type = SceneLightType::Spot;
    else if (gl.type == "point")
        light.type = SceneLightType::Point;
    else {
        warn("light '" + light.name + "': unknown type '" + gl.type + "'; ignored");
        return std::nullopt;
    }
    // The position limit of the light.position key (1e7, HARD_CASES 3): a light 1e30 away would only end in a
    // light volume whose near and far planes cannot be told apart.
    const NodeFrame frame = nodeFrame(world);
    const glm::dvec3& position = frame.position;
    if (!(std::max({std::abs(position.x), std::abs(position.y), std::abs(position.z)}) <= kMaxLightPosition)) {
        warn("light '" + light.name + "': position (" + str(position.x) + ", " + str(position.y) + ", " +
             str(position.z) + ") has a component beyond " + str(kMaxLightPosition) + " (the light.position limit); ignored");
        return std::nullopt;
    }
    light.position = glm::vec3(position);
    if (frame.forward)  // the light shines along its node's -Z
        light.direction = glm::vec3(*frame.forward);
    else
        warn("light '" + light.name + "': its node's transform has no -Z direction; (0,0,-1) used");
    if (light.type == SceneLightType::Spot) {
        const double outer = gl.spot.outerConeAngle;
        light.outerConeRad = float(std::isfinite(outer) ? std::clamp(outer, 1e-4, 1.5707963267948966) : 0.7853981634);
    }
    if (fitsFloat(gl.range) && gl.range > 0.0) light.range = float(gl.range);
    if (gl.color.size() == 3 && fitsFloat(gl.color[0]) && fitsFloat(gl.color[1]) && fitsFloat(gl.color[2]))
        light.color = glm::vec3(float(gl.color[0]), float(gl.color[1]), float(gl.color[2]));
    if (fitsFloat(gl.intensity) && gl.intensity >= 0.0) light.intensity = float(gl.intensity);
    return light;
}

}  // namespace shadowlab::gltf
