// HARD_CASES 8: spot light perspective aliasing. A wider cone spreads the same map over more of the world: at 120
// deg, 1024^2 and z = 20 a texel covers 0.068 units. The edge error in camera pixels should track the predicted
// texel / pixel ratio (a texel's world size at the receivers over a camera pixel's there): the ratio of the two stays
// within a band across cones 30, 90, 120, 170 deg. 179 and 180 deg (glm::perspective(180) flips a sign) are refused.
#include "hardcases/cases.h"

#include "light/light_space.h"
#include "scene/builtin_scenes.h"
#include "settings/settings_fields.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab::hardcases {

void runSpotAliasing(CaseContext& context, CaseResult& result) {
    const Scene scene = *makeBuiltinScene("textbook");
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    Settings s;
    LightSettings& light = s.lights[0];
    light.type = LightType::Spot;
    light.position = {0.0f, 6.0f, 0.0f};
    light.direction = {0.15f, -1.0f, 0.1f};
    light.shadow.resolution = context.pick(1024, 512);
    light.shadow.normalOffset = 1.0f;
    s.filter.kind = FilterKind::Point;
    const Camera camera = cameraFor(s.camera, scene, double(width) / double(height));
    // The receivers of interest: the floor around the cube, at the cube's shadow.
    const glm::dvec3 receiver(0.6, 0.0, 0.4);
    const double pixelWorld = glm::length(receiver - camera.position) * 2.0 *
                              std::tan(glm::radians(camera.fovYDeg) / 2.0) / double(height);
    struct Run {
        double cone, nearPlane;  // nearPlane 0: auto-fitted
    };
    std::vector<Run> runs = {{30, 0}, {90, 0}, {120, 0}, {170, 0}};
    if (!context.quick()) runs.insert(runs.end(), {{120, 0.05}, {120, 0.5}});
    std::vector<double> quotients;
    for (const Run& run : runs) {
        light.spotConeDeg = float(run.cone);
        light.projection.autoFit = run.nearPlane == 0.0;
        if (!light.projection.autoFit) {
            light.projection.nearPlane = float(run.nearPlane);
            light.projection.farPlane = 30.0f;
        }
        std::string error;
        const std::optional<LightSpace> space = buildLightSpace(light, scene.bounds, glm::dvec3(0.0), error);
        if (!space) throw std::runtime_error(error);
        const double depth = glm::dot(receiver - glm::dvec3(light.position), space->direction);
        const double ratio = space->texelSizeAt(depth) / pixelWorld;
        const std::string name = "cone" + std::to_string(int(run.cone)) +
                                 (run.nearPlane > 0 ? "-near" + figure(run.nearPlane) : "");
        const AccuracyReport r = context.measure(scene, s, width, height, name);
        if (!r.ok) throw std::runtime_error(name + ": " + r.error);
        // Point filter: a mismatch lies within about a texel of the true edge, so edge error ~ (k + 1) x ratio px;
        // x 2 for the texels off the cone's axis (a spot's texel grows as 1 / cos^2 of the angle off it).
        const double predicted = 2.0 * (r.kTexels + 1.0) * ratio;
        const double quotient = r.edgeErrorP95ScreenPixels / std::max(predicted, 1.0);
        quotients.push_back(quotient);
        result.check(figure(run.cone) + " deg" + (run.nearPlane > 0 ? ", near " + figure(run.nearPlane) : "") +
                         ": edge error p95 (texel/pixel ratio " + figure(ratio) + ")",
                     figure(r.edgeErrorP95ScreenPixels, "px"), "<= 2 (k+1) x ratio = " + figure(std::max(predicted, 1.0), "px") + " (floor 1 px)",
                     r.edgeErrorP95ScreenPixels <= std::max(predicted, 1.0));
    }
    const auto [lo, hi] = std::minmax_element(quotients.begin(), quotients.end());
    result.info("edge error / predicted, over the cones", figure(*lo) + " .. " + figure(*hi), "tracking: a narrow band");
    for (const char* cone : {"179", "180"}) {
        Settings refused;
        refused.lights[0].type = LightType::Spot;
        const std::string why = applySettingOverride(refused, std::string("lights.0.spotConeDeg=") + cone);
        result.check(std::string(cone) + " deg: refused", why.empty() ? "accepted" : why,
                     "a message naming lights.0.spotConeDeg", why.find("lights.0.spotConeDeg") != std::string::npos);
    }
}

}  // namespace shadowlab::hardcases
