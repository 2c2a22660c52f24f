// HARD_CASES 3: a city-sized scene (170 units) moved by T in {0, 1e3, 1e4, 1e5, 1e6} on x and z; the float32 step is
// 0.0625 at 1e6. In screen space the mask must not depend on T: edge error(T) <= edge error(0) + 0.5 texel. Then the
// camera moves 1 mm per frame at 1e6 with the light still: no view re-rendered, flicker 0.
#include "hardcases/cases.h"

#include "hardcases/hard_case_scenes.h"

namespace shadowlab::hardcases {

void runLargeWorld(CaseContext& context, CaseResult& result) {
    const Scene city = cityScene();
    const std::vector<double> offsets =
        context.quick() ? std::vector<double>{0.0, 1e5, 1e6} : std::vector<double>{0.0, 1e3, 1e4, 1e5, 1e6};
    Settings s;
    s.lights[0].shadow.resolution = context.pick(2048, 1024);
    s.lights[0].shadow.normalOffset = 1.0f;
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    double edge0 = 0.0;
    Scene farthest;
    for (double t : offsets) {
        const Scene moved = translated(city, glm::vec3(float(t), 0.0f, float(t)));
        const AccuracyReport r = context.measure(moved, s, width, height, "T" + std::to_string((long long)t));
        if (!r.ok) throw std::runtime_error("T = " + figure(t) + ": " + r.error);
        if (t == 0.0) {
            edge0 = r.edgeErrorP95Texels;
            result.info("T = 0: edge error p95 (wrong pixels " + percent(r.wrongPercent) + ")",
                        figure(r.edgeErrorP95Texels, "texels"), "the reference for T > 0");
        } else {
            result.check("T = " + figure(t, "", 1) + ": edge error p95 (wrong pixels " + percent(r.wrongPercent) + ")",
                         figure(r.edgeErrorP95Texels, "texels"), "<= " + figure(edge0 + 0.5, "texels"),
                         r.edgeErrorP95Texels <= edge0 + 0.5);
        }
        farthest = moved;
    }
    // The camera 1 mm per frame along its right vector at T = 1e6, the light still.
    Motion motion;
    motion.kind = MotionKind::Camera;
    motion.step = 1e-3;
    motion.frames = context.pick(10, 3);
    const FlickerReport f = context.flicker(farthest, s, width, height, motion, "T1e6-camera");
    if (!f.ok) throw std::runtime_error(f.error);
    std::size_t rerendered = 0;
    for (const FlickerPair& pair : f.pairs) rerendered += pair.shadowViewsRendered;
    result.check("T = 1e6, camera +1 mm x " + std::to_string(f.pairs.size()) + ": shadow views re-rendered",
                 std::to_string(rerendered), "0 (the light is still)", rerendered == 0);
    result.check("T = 1e6, camera +1 mm: flicker, worst pair", percent(f.maxFlickerPercent), "0",
                 f.maxFlickerPercent == 0.0);
}

}  // namespace shadowlab::hardcases
