// HARD_CASES 6: border texels and PCF crossing the border. A 512^2 map over an ortho [-10, 10]^2 volume, a caster quad
// spanning x in [9.9, 12] (it crosses the volume's edge), a receiver over [-20, 20]^2. Outside the volume the shadow
// factor must follow the address-mode policy (clamp-to-border with border depth 1: lit); inside, a 5x5 PCF kernel at
// u < 2/512 reads texels beyond the edge, yet the error there must match the same edge in the interior.
// A map smaller than its texture (an atlas tile) and a guard band do not exist in the renderer (every map fills its
// own texture layer); the non-power-of-two map is what can be tested of "a map not of the usual size".
#include "hardcases/cases.h"

#include "hardcases/hard_case_scenes.h"

#include <glm/ext/matrix_transform.hpp>

namespace shadowlab::hardcases {

namespace {

Scene borderScene(float casterMinX) {
    Scene scene = meshKit("border");
    addFloor(scene, 40.0f);
    // The floor quad scaled to 2.1 x 2 at height 1, its near edge at casterMinX.
    const glm::mat4 caster = glm::translate(glm::mat4(1.0f), {casterMinX + 1.05f, 1.0f, 0.0f});
    scene.instances.push_back({0, glm::scale(caster, glm::vec3(2.1f / 20.0f, 1.0f, 2.0f / 20.0f))});
    scene.computeBounds();
    return scene;
}

// The shadow factor (0..1) where a world point lands in a shadow view; -1 off screen.
double shadowAt(const RenderedView& v, const glm::dvec3& world) {
    double px = 0.0, py = 0.0;
    if (!projectToPixel(v.stats, world, v.width, v.height, px, py)) return -1.0;
    return v.red(int(px), int(py)) / 255.0;
}

// Outside the volume (|x| or |z| beyond 10.25, on a 0.25 grid of the receiver): how many samples are not lit.
int shadowedOutside(const RenderedView& v, int& total) {
    int dark = 0;
    total = 0;
    for (double x = -19.875; x < 20.0; x += 0.25)
        for (double z = -19.875; z < 20.0; z += 0.25) {
            if (std::abs(x) < 10.25 && std::abs(z) < 10.25) continue;
            const double s = shadowAt(v, {x, 0.0, z});
            if (s < 0.0) continue;
            ++total;
            dark += s < 0.5;
        }
    return dark;
}

// Wrong pixels (|S - V| >= 0.5) whose cause is not "outside the light's volume", per measured pixel, in percent.
double wrongInside(const AccuracyReport& r) {
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < r.pixelClass.size(); ++i) {
        if (!r.pixelMeasured[i] || r.pixelCause[i] == MismatchCause::OutsideVolume) continue;
        const double v = r.pixelClass[i] == PixelClass::Lit ? 1.0 : 0.0;
        wrong += std::abs(double(r.pixelShadow[i]) - v) >= 0.5;
    }
    return r.counts.measured ? 100.0 * double(wrong) / double(r.counts.measured) : 0.0;
}

}  // namespace

void runBorderTexels(CaseContext& context, CaseResult& result) {
    Settings s;
    LightSettings& light = s.lights[0];
    light.direction = {0.0f, -1.0f, 0.0f};
    light.shadow.resolution = 512;
    light.shadow.normalOffset = 1.0f;
    light.projection.autoFit = false;
    light.projection.orthoSize = 20.0f;
    light.projection.nearPlane = 0.1f;
    light.projection.farPlane = 60.0f;
    s.filter.kind = FilterKind::Pcf;
    s.filter.kernel = 5;
    s.sampler.addressMode = AddressMode::ClampToBorder;
    s.sampler.borderDepth = 1.0f;
    const Scene scene = borderScene(9.9f);
    const int size = context.pick(400, 200);

    // The policy outside the volume, seen from straight above the whole receiver.
    Settings top = s;
    top.view = ViewMode::Shadow;
    top.camera.autoFrame = false;
    top.camera.position = {0.0, 50.0, 0.0};
    top.camera.target = {0.0, 0.0, 0.0};
    int total = 0;
    const RenderedView border = context.render(scene, top, size, size, "outside-border");
    const int borderDark = shadowedOutside(border, total);
    result.check("clamp to border, border depth 1: outside samples shadowed", std::to_string(borderDark) + " of " +
                 std::to_string(total), "0 (policy: lit outside)", total > 0 && borderDark == 0);
    top.sampler.addressMode = AddressMode::ClampToEdge;
    const int edgeDark = shadowedOutside(context.render(scene, top, size, size, "outside-edge"), total);
    result.info("clamp to edge: outside samples shadowed", std::to_string(edgeDark) + " of " + std::to_string(total),
                "the caster touching the edge smears into a streak");
    top.sampler.addressMode = AddressMode::Wrap;
    const int wrapDark = shadowedOutside(context.render(scene, top, size, size, "outside-wrap"), total);
    result.info("wrap: outside samples shadowed", std::to_string(wrapDark) + " of " + std::to_string(total),
                "the opposite edge's texels repeat outside");

    // Inside: the caster's edge at x = 9.9 (2.6 texels from the border) vs the same edge in the interior (x = -0.6),
    // each seen from straight above; pixels outside the volume do not count (their cause is the policy).
    const auto edgeCamera = [](Settings v, double x) {
        v.camera.autoFrame = false;
        v.camera.position = {x, 8.0, 0.0};
        v.camera.target = {x, 0.0, 0.001};
        return v;
    };
    const AccuracyReport atBorder = context.measure(scene, edgeCamera(s, 8.5), size, size, "edge-at-border");
    const AccuracyReport interior = context.measure(borderScene(-0.6f), edgeCamera(s, -2.0), size, size, "edge-interior");
    if (!atBorder.ok || !interior.ok) throw std::runtime_error(atBorder.ok ? interior.error : atBorder.error);
    const double wb = wrongInside(atBorder), wi = wrongInside(interior);
    result.check("PCF 5x5 at u < 3/512: wrong pixels inside the volume (interior: " + percent(wi) + ")", percent(wb),
                 "<= interior + 0.1 %", wb <= wi + 0.1);
    // A non-power-of-two map: the same policy and the same border error.
    Settings npot = s;
    npot.lights[0].shadow.resolution = 500;
    top = s;
    top.lights[0].shadow.resolution = 500;
    top.view = ViewMode::Shadow;
    top.camera.autoFrame = false;
    top.camera.position = {0.0, 50.0, 0.0};
    top.camera.target = {0.0, 0.0, 0.0};
    const int npotDark = shadowedOutside(context.render(scene, top, size, size), total);
    const AccuracyReport npotBorder = context.measure(scene, edgeCamera(npot, 8.5), size, size, "edge-at-border-500");
    if (!npotBorder.ok) throw std::runtime_error(npotBorder.error);
    result.check("500^2 map: outside samples shadowed; wrong pixels at the border",
                 std::to_string(npotDark) + "; " + percent(wrongInside(npotBorder)),
                 "0; <= interior + 0.1 %", npotDark == 0 && wrongInside(npotBorder) <= wi + 0.1);
    result.notRun("a map smaller than its texture (atlas tile)", "the same policy at the tile's edge",
                  "the renderer has no atlas or sub-rectangle viewport: each map fills its texture");
    result.notRun("a one-texel guard band", "the tile's border texels lit", "the renderer keeps no guard band");
}

}  // namespace shadowlab::hardcases
