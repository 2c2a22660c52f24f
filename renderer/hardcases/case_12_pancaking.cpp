// HARD_CASES 12: casters before the light's near plane ("pancaking"). The near plane is fitted to the receivers (the
// floor), and a tower pokes 5 units through it toward the light. With GL_DEPTH_CLAMP the clipped part is clamped to
// the near plane and still casts (leak 0); without it, it is clipped away and its shadow goes (a leak is expected).
#include "hardcases/cases.h"

#include "hardcases/hard_case_scenes.h"
#include "light/light_space.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace shadowlab::hardcases {

void runPancaking(CaseContext& context, CaseResult& result) {
    Scene floorOnly = meshKit("pancake-floor");
    addFloor(floorOnly, 20.0f);
    Settings s;
    s.lights[0].shadow.resolution = context.pick(2048, 512);
    s.lights[0].shadow.normalOffset = 1.0f;
    // The auto-fitted volume of the floor alone gives the light's eye and direction; depths are measured from it.
    std::string error;
    const std::optional<LightSpace> fitted =
        buildLightSpace(s.lights[0], floorOnly.bounds, glm::dvec3(0.0), error);
    if (!fitted) throw std::runtime_error(error);
    const auto depthOf = [&](const glm::dvec3& p) { return glm::dot(p - fitted->position, fitted->direction); };
    double nearest = 1e30, farthest = -1e30;
    for (double x : {-10.0, 10.0})
        for (double z : {-10.0, 10.0}) {
            nearest = std::min(nearest, depthOf({x, 0.0, z}));
            farthest = std::max(farthest, depthOf({x, 0.0, z}));
        }
    // A tower at the centre whose top lies 5 units before the near plane along the light.
    const double up = -fitted->direction.y;
    const double towerHeight = (depthOf({0.0, 0.0, 0.0}) - nearest + 5.0) / up;
    Scene scene = floorOnly;
    scene.name = "pancake-tower";
    addBox(scene, {0.0f, float(0.5 * towerHeight), 0.0f}, {1.0f, float(towerHeight), 1.0f});
    // The volume of the floor, with the eye where the fitted floor had it: the bounds now include the tower.
    const std::optional<LightSpace> withTower = buildLightSpace(s.lights[0], scene.bounds, glm::dvec3(0.0), error);
    if (!withTower) throw std::runtime_error(error);
    const double shift = glm::dot(fitted->position - withTower->position, withTower->direction);
    LightSettings& light = s.lights[0];
    light.projection.autoFit = false;
    light.projection.orthoSize = float(withTower->orthoSize);
    light.projection.nearPlane = float(nearest + shift - 0.01);
    light.projection.farPlane = float(farthest + shift + 0.01);
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    light.projection.depthClamp = true;
    const AccuracyReport clamped = context.measure(scene, s, width, height, "depth-clamp-on");
    light.projection.depthClamp = false;
    const AccuracyReport clipped = context.measure(scene, s, width, height, "depth-clamp-off");
    if (!clamped.ok || !clipped.ok) throw std::runtime_error(clamped.ok ? clipped.error : clamped.error);
    result.info("tower height / part before the near plane", figure(towerHeight, "units") + " / 5 units along the light",
                "the near plane fitted to the floor's nearest corner");
    result.check("leak, depth clamp on", percent(clamped.leakPercent), "0 (<= 0.1 %)", clamped.leakPercent <= 0.1);
    result.check("leak, depth clamp off", percent(clipped.leakPercent), "> 0 (expected)", clipped.leakPercent > 0.1);
    result.check("  of its wrong pixels caused by the near-plane clip",
                 percent(clipped.causePercentOfWrong(MismatchCause::NearPlaneClip)), "> 50 %",
                 clipped.causePercentOfWrong(MismatchCause::NearPlaneClip) > 50.0);
}

}  // namespace shadowlab::hardcases
