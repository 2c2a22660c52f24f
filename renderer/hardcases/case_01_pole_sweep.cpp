// HARD_CASES 1: the light swept across straight down, L(t) = (sin t, -cos t, 0), t in [-1e-3, 1e-3] rad in 1e-5
// steps, over AlphaBlendModeTest. The textbook lookAt(up = +y) gives NaN at t = 0 and turns the map 180 degrees
// across it; the light basis must stay finite and continuous, so acne and leak stay low for every t.
#include "hardcases/cases.h"

#include "light/light_space.h"

#include <algorithm>
#include <cmath>

namespace shadowlab::hardcases {

void runPoleSweep(CaseContext& context, CaseResult& result) {
    std::string why;
    const std::optional<Scene> scene = context.sharedScene("AlphaBlendModeTest/AlphaBlendModeTest.gltf", why);
    if (!scene) {
        result.notRun("the sweep over AlphaBlendModeTest", "", why);
        return;
    }
    // Full: every 1e-5 step; quick: the ends, the pole and its neighbours.
    std::vector<int> steps;
    if (context.quick())
        steps = {-100, -1, 0, 1, 100};
    else
        for (int k = -100; k <= 100; ++k) steps.push_back(k);
    const int width = context.pick(320, 160), height = context.pick(180, 90);
    Settings s;
    s.lights[0].shadow.resolution = context.pick(2048, 512);
    s.lights[0].shadow.normalOffset = 1.0f;  // texel-relative: the shipped multi-light presets' bias
    int finite = 0;
    double worstAcne = 0.0, worstLeak = 0.0, acneAt = 0.0, leakAt = 0.0;
    for (int k : steps) {
        const double t = k * 1e-5;
        s.lights[0].direction = glm::vec3(float(std::sin(t)), float(-std::cos(t)), 0.0f);
        std::string error;
        const std::optional<LightSpace> space =
            buildLightSpace(s.lights[0], scene->bounds, glm::dvec3(scene->bounds.center()), error);
        if (space && allFinite(space->viewProjection())) ++finite;
        const std::string picture = k == -1 ? "t-1e-5" : k == 0 ? "t0" : k == 1 ? "t+1e-5" : "";
        const AccuracyReport r = context.measure(*scene, s, width, height, picture);
        if (!r.ok) throw std::runtime_error("t = " + figure(t) + ": " + r.error);
        if (r.acnePercent >= worstAcne) worstAcne = r.acnePercent, acneAt = t;
        if (r.leakPercent >= worstLeak) worstLeak = r.leakPercent, leakAt = t;
    }
    const int n = int(steps.size());
    result.check("light matrices finite, of " + std::to_string(n) + " t", std::to_string(finite) + " of " + std::to_string(n),
                 "all", finite == n);
    result.check("acne, worst t (" + figure(acneAt) + ")", percent(worstAcne), "< 0.1 %", worstAcne < 0.1);
    result.check("leak, worst t (" + figure(leakAt) + ")", percent(worstLeak), "< 0.1 %", worstLeak < 0.1);
    result.notRun("flicker between adjacent t", "< share of pixels where V changed",
                  "needs the flicker measure, renderer/accuracy/flicker.h (issue 14)");
}

}  // namespace shadowlab::hardcases
