// HARD_CASES 9: point light cube seams. Bilinear and PCF taps do not cross cube faces unless the lookup is seamless,
// and a kernel laid out in one face's 2D space runs off it. builtin:room puts the light at the centre of a closed
// room with a pillar and a table whose shadows cross the faces' edges. Pixels whose direction from the light has its
// two largest components within one texel of each other (|major| ~ |minor|) form the seam band: acne and leak there
// must equal those of the interior.
#include "hardcases/cases.h"

#include "scene/builtin_scenes.h"

#include <algorithm>
#include <cmath>

namespace shadowlab::hardcases {

namespace {

struct Counts {
    std::size_t pixels = 0, lit = 0, shadowed = 0, acne = 0, leak = 0;
    double acnePercent() const { return lit ? 100.0 * double(acne) / double(lit) : 0.0; }
    double leakPercent() const { return shadowed ? 100.0 * double(leak) / double(shadowed) : 0.0; }
};

}  // namespace

void runCubeSeams(CaseContext& context, CaseResult& result) {
    const Scene room = *makeBuiltinScene("room");
    Settings s;
    LightSettings& light = s.lights[0];
    light.type = LightType::Point;
    light.position = builtin::kRoomLight;
    light.range = builtin::kRoomLightRange;
    light.shadow.resolution = context.pick(1024, 256);
    light.shadow.normalOffset = 1.0f;  // presets/room.json's bias: 2 / 2 / 1
    s.camera.autoFrame = false;        // inside the room's -z end, as presets/room.json
    s.camera.position = {4.6, 5.6, -6.6};
    s.camera.target = {1.5, 0.5, 3.5};
    s.camera.fovYDeg = 60.0f;
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    const AccuracyReport r = context.measure(room, s, width, height, "room");
    if (!r.ok) throw std::runtime_error(r.error);
    const SurfaceSamples surfaces = context.surfaces(room, s, width, height);
    const double texel = 2.0 / light.shadow.resolution;  // of a face coordinate in [-1, 1]
    Counts band, interior;
    for (std::size_t i = 0; i < r.pixelClass.size() && i < surfaces.size(); ++i) {
        if (!r.pixelMeasured[i] || !surfaces.isSurface(i)) continue;
        const glm::dvec3 d = glm::abs(surfaces.point[i] - glm::dvec3(builtin::kRoomLight));
        double c[3] = {d.x, d.y, d.z};
        std::sort(c, c + 3);
        Counts& k = 1.0 - c[1] / c[2] <= texel ? band : interior;
        ++k.pixels;
        const bool lit = r.pixelClass[i] == PixelClass::Lit;
        k.lit += lit;
        k.shadowed += !lit;
        k.acne += r.pixelMark[i] == PixelMark::Acne;
        k.leak += r.pixelMark[i] == PixelMark::Leak;
    }
    result.info("seam band / interior pixels", std::to_string(band.pixels) + " / " + std::to_string(interior.pixels),
                "band: the two largest |components| within one texel (" + figure(texel) + " of a face)");
    result.check("acne in the seam band (interior " + percent(interior.acnePercent()) + ")", percent(band.acnePercent()),
                 "<= interior + 0.1 %", band.pixels > 0 && band.acnePercent() <= interior.acnePercent() + 0.1);
    result.check("leak in the seam band (interior " + percent(interior.leakPercent()) + ")", percent(band.leakPercent()),
                 "<= interior + 0.1 %", band.pixels > 0 && band.leakPercent() <= interior.leakPercent() + 0.1);
    result.info("whole view: acne / leak / wrong pixels",
                percent(r.acnePercent) + " / " + percent(r.leakPercent) + " / " + percent(r.wrongPercent), "");
}

}  // namespace shadowlab::hardcases
