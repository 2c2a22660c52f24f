// HARD_CASES 11: alpha-tested casters. The depth pass must apply baseColor alpha x factor against the cutoff with
// the same UV set and texture transform as the reference; mip selection in the shadow pass thins coverage.
// AlphaBlendModeTest with every MASK material's cutoff at 0.25, 0.5 and 0.75 and the sun at 30 deg elevation: the
// mask matches the alpha-aware reference (edge error <= k), and the shadow moves when the cutoff changes.
#include "hardcases/cases.h"

#include <glm/trigonometric.hpp>

#include <cmath>

namespace shadowlab::hardcases {

void runAlphaCutoffs(CaseContext& context, CaseResult& result) {
    std::string why;
    const std::optional<Scene> loaded = context.sharedScene("AlphaBlendModeTest/AlphaBlendModeTest.gltf", why);
    if (!loaded) {
        result.notRun("cutoffs 0.25 / 0.5 / 0.75", "edge error <= k", why);
        return;
    }
    Settings s;
    const double elevation = glm::radians(30.0);
    s.lights[0].direction = glm::vec3(0.3f, float(-std::sin(elevation)), float(-std::cos(elevation)));
    s.lights[0].shadow.resolution = context.pick(2048, 1024);
    s.lights[0].shadow.normalOffset = 1.0f;
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    std::vector<std::vector<float>> shadows;
    std::vector<std::vector<PixelClass>> classes;
    for (float cutoff : {0.25f, 0.5f, 0.75f}) {
        Scene scene = *loaded;
        int masked = 0;
        for (Material& m : scene.materials)
            if (m.alphaMode == AlphaMode::Mask) m.alphaCutoff = cutoff, ++masked;
        const AccuracyReport r = context.measure(scene, s, width, height, "cutoff" + figure(cutoff));
        if (!r.ok) throw std::runtime_error(r.error);
        result.check("cutoff " + figure(cutoff) + " (" + std::to_string(masked) + " MASK materials): edge error p95",
                     figure(r.edgeErrorP95Texels, "texels") + " (alpha-test cause " +
                         percent(r.causePercentOfWrong(MismatchCause::AlphaTest)) + " of wrong)",
                     "<= k = " + figure(r.kTexels, "texels"), r.edgeErrorP95Texels <= r.kTexels);
        shadows.push_back(r.pixelShadow);
        classes.push_back(r.pixelClass);
    }
    // The shadow moves: pixels whose S and whose exact V differ between cutoff 0.25 and 0.75.
    std::size_t sMoved = 0, vMoved = 0;
    for (std::size_t i = 0; i < shadows[0].size(); ++i) {
        sMoved += (shadows[0][i] >= 0.5f) != (shadows[2][i] >= 0.5f);
        vMoved += (classes[0][i] == PixelClass::Lit) != (classes[2][i] == PixelClass::Lit);
    }
    result.check("cutoff 0.25 -> 0.75: pixels whose S flips (V flips: " + std::to_string(vMoved) + ")",
                 std::to_string(sMoved), "> 0, as V", sMoved > 0 && vMoved > 0);
}

}  // namespace shadowlab::hardcases
