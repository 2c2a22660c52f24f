// HARD_CASES 10: Peter Panning of thin casters. The leak's width is about bias / tan(theta), and culling front faces
// in the shadow pass fails for single-sided planes. builtin:thin-walls (walls 0.02, 0.1 and 0.5 thick) under a light
// at 45 and 80 deg from the vertical, with texel-relative biases: no light may leak more than one texel past a wall's
// contact line (DESIGN's leak, beyond k = 1 texel with a point filter). The full run adds IntelSponza_Curtains and
// FlightHelmet (its straps).
#include "hardcases/cases.h"

#include "scene/builtin_scenes.h"

#include <glm/trigonometric.hpp>

#include <cmath>

namespace shadowlab::hardcases {

void runThinCasters(CaseContext& context, CaseResult& result) {
    Settings s;
    // 2048^2 also with --quick: at 1024^2 a texel (0.028) is wider than the thinnest wall (0.02). The default bias
    // (2 / 2 / half a texel of normal offset): a whole texel (0.014) reaches far enough through the 0.02 wall at 45
    // deg to light a pixel or two behind it (0.06 % at 480x270).
    s.lights[0].shadow.resolution = 2048;
    s.filter.kind = FilterKind::Point;  // k = 1 texel
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    const Scene walls = *makeBuiltinScene("thin-walls");
    for (double angle : {45.0, 80.0}) {
        // Toward -z across the walls (they run along x), tilted a little along x so no edge is axis-aligned.
        const double a = glm::radians(angle);
        s.lights[0].direction = glm::vec3(0.15f, float(-std::cos(a)), float(-std::sin(a)));
        const AccuracyReport r = context.measure(walls, s, width, height, "thin-walls-" + figure(angle));
        if (!r.ok) throw std::runtime_error(r.error);
        result.check("thin-walls, light " + figure(angle) + " deg: leak beyond 1 texel (acne " +
                         percent(r.acnePercent) + ")",
                     percent(r.leakPercent), "<= 0.1 %", r.leakPercent <= 0.1);
    }
    if (context.quick()) return;
    s.lights[0] = LightSettings{};
    s.lights[0].shadow.resolution = 2048;
    // The default bias leaks 0.14 % (FlightHelmet) and 0.52 % (curtains) beyond a texel, all of it "bias larger than
    // the caster-receiver gap" in thin folds and straps: case 2's remedy, a clamp on the slope term, ends it.
    s.lights[0].shadow.depthBiasClamp = 2e-4f;
    for (const char* file : {"IntelSponza_Curtains_geometry/sponza_curtains.gltf", "FlightHelmet_geometry/FlightHelmet.gltf"}) {
        std::string why;
        const std::optional<Scene> scene = context.sharedScene(file, why);
        const std::string name = std::string(file).substr(std::string(file).find('/') + 1);
        if (!scene) {
            result.notRun(name + ": leak beyond 1 texel", "<= 0.1 %", why);
            continue;
        }
        const AccuracyReport r = context.measure(*scene, s, width, height, name.substr(0, name.find('.')));
        if (!r.ok) throw std::runtime_error(name + ": " + r.error);
        result.check(name + ", default light, clamp 2e-4: leak beyond 1 texel (acne " + percent(r.acnePercent) + ")",
                     percent(r.leakPercent), "<= 0.1 %", r.leakPercent <= 0.1);
    }
}

}  // namespace shadowlab::hardcases
