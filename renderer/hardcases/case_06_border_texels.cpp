// HARD_CASES 6: border texels and PCF crossing the border. A 512^2 map over an ortho [-10, 10]^2 volume, a caster quad
// spanning x in [9.9, 12] (it crosses the volume's edge), a receiver over [-20, 20]^2. Outside the volume the shadow
// factor must follow the address-mode policy (clamp-to-border with border depth 1: lit); inside, a 5x5 PCF kernel at
// u < 2/512 reads texels beyond the edge, yet the error there (mean |S - V|) must match the same edge in the interior.
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

// The mean |S - V| over the measured pixels whose world x lies in [xMin, xMax) (the volume's inside near its edge);
// `pixels` gets their count. (Wrong pixels, |S - V| >= 0.5, are too coarse here: a 5x5 kernel within 2.6 texels of
// the edge stays below 0.5 on both sides.)
double meanErrorBetween(const AccuracyReport& r, const SurfaceSamples& surfaces, double xMin, double xMax,
                    std::size_t& pixels) {
    double error = 0.0;
    pixels = 0;
    for (std::size_t i = 0; i < r.pixelClass.size() && i < surfaces.size(); ++i) {
        if (!r.pixelMeasured[i] || !surfaces.isSurface(i)) continue;
        const double x = surfaces.point[i].x;
        if (x < xMin || x >= xMax) continue;
        ++pixels;
        const double v = r.pixelClass[i] == PixelClass::Lit ? 1.0 : 0.0;
        error += std::abs(double(r.pixelShadow[i]) - v);
    }
    return pixels ? error / double(pixels) : 0.0;
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

    // Inside: the floor under the caster, seen from low on the -x side through the 1-unit gap beneath it (the
    // caster's underside is a back face: not drawn). Its shadow there lies within u < 3/512 of the border at
    // x = 10 (x in [9.9, 10)); the control is the same caster and view 10 units further in (x in [-0.1, 0)): a whole number of texels at 512^2
    // and 500^2 (256 and 250), so the edge sits at the same place within its texel.
    const auto edgeCamera = [](Settings v, double shift) {
        v.camera.autoFrame = false;
        v.camera.position = {9.4 + shift, 0.5, 0.0};
        v.camera.target = {10.0 + shift, 0.0, 0.0};
        return v;
    };
    const auto measureEdge = [&](const Scene& sc, const Settings& v, double shift, const std::string& picture,
                                 std::size_t& pixels) {
        const AccuracyReport r = context.measure(sc, edgeCamera(v, shift), size, size, picture);
        if (!r.ok) throw std::runtime_error(picture + ": " + r.error);
        return meanErrorBetween(r, context.surfaces(sc, edgeCamera(v, shift), size, size), 9.9 + shift, 10.0 + shift,
                            pixels);
    };
    std::size_t nb = 0, ni = 0, nn = 0;
    const double wb = measureEdge(scene, s, 0.0, "edge-at-border", nb);
    const double wi = measureEdge(borderScene(-0.1f), s, -10.0, "edge-interior", ni);
    result.check("PCF 5x5, u < 3/512 (x in [9.9, 10), " + std::to_string(nb) + " px): mean |S-V| (interior: " +
                     figure(wi) + ")",
                 figure(wb), "<= interior + 0.01", nb > 0 && ni > 0 && wb <= wi + 0.01);

    // A non-power-of-two map: the same policy and the same border error.
    Settings npot = s;
    npot.lights[0].shadow.resolution = 500;
    top = npot;
    top.view = ViewMode::Shadow;
    top.camera.autoFrame = false;
    top.camera.position = {0.0, 50.0, 0.0};
    top.camera.target = {0.0, 0.0, 0.0};
    const int npotDark = shadowedOutside(context.render(scene, top, size, size), total);
    std::size_t nni = 0;
    const double wn = measureEdge(scene, npot, 0.0, "edge-at-border-500", nn);
    const double wni = measureEdge(borderScene(-0.1f), npot, -10.0, "edge-interior-500", nni);
    result.check("500^2 map: outside samples shadowed; mean |S-V| at the border (interior: " + figure(wni) + ")",
                 std::to_string(npotDark) + "; " + figure(wn), "0; <= interior + 0.01",
                 npotDark == 0 && nn > 0 && nni > 0 && wn <= wni + 0.01);
    result.notRun("a map smaller than its texture (atlas tile)", "the same policy at the tile's edge",
                  "the renderer has no atlas or sub-rectangle viewport: each map fills its texture");
    result.notRun("a one-texel guard band", "the tile's border texels lit", "the renderer keeps no guard band");
}

}  // namespace shadowlab::hardcases
