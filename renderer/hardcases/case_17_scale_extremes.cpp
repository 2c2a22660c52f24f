// HARD_CASES 17: scale extremes and constant biases. Scenes from 0.7 units (FlightHelmet) over 25 (Lantern) and 170
// (a built city) to 745 (2CylinderEngine of assimp-testmodels): a bias in world units that suits one fails the
// others, so the same texel-relative setting (DepthBias 2 in format steps, SlopeScaledDepthBias 2, half a texel of normal
// offset, case 2's slope clamp 2e-4) is measured on all with case 2's metrics: acne and leak beyond k.
#include "hardcases/cases.h"

#include "hardcases/hard_case_scenes.h"

namespace shadowlab::hardcases {

void runScaleExtremes(CaseContext& context, CaseResult& result) {
    Settings s;
    s.lights[0].shadow.resolution = 2048;
    s.lights[0].shadow.depthBiasClamp = 2e-4f;  // case 10's setting: the default bias with case 2's slope clamp
    s.filter.kind = FilterKind::Point;
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    struct Entry {
        std::string name;
        std::optional<Scene> scene;
        std::string why;
    };
    std::vector<Entry> entries;
    entries.push_back({"FlightHelmet", {}, ""});
    entries.back().scene = context.sharedScene("FlightHelmet_geometry/FlightHelmet.gltf", entries.back().why);
    entries.push_back({"Lantern", {}, ""});
    entries.back().scene = context.sharedScene("Lantern_geometry/Lantern.gltf", entries.back().why);
    entries.push_back({"city", cityScene(), ""});
    entries.push_back({"2CylinderEngine", {}, ""});
    entries.back().scene = context.assimpScene("2CylinderEngine-glTF-Binary/2CylinderEngine.glb", entries.back().why);
    for (Entry& e : entries) {
        if (!e.scene) {
            result.notRun(e.name + ": acne / leak", "< 0.1 %", e.why);
            continue;
        }
        const double size = 2.0 * double(e.scene->bounds.radius());
        const AccuracyReport r = context.measure(*e.scene, s, width, height, e.name);
        if (!r.ok) throw std::runtime_error(e.name + ": " + r.error);
        result.check(e.name + " (" + figure(size, "units") + " diagonal): acne / leak beyond k (wrong " +
                         percent(r.wrongPercent) + ")",
                     percent(r.acnePercent) + " / " + percent(r.leakPercent), "< 0.1 % each",
                     r.acnePercent < 0.1 && r.leakPercent < 0.1);
    }
}

}  // namespace shadowlab::hardcases
