// Bias presets on the grazing plane, address modes outside the map, and filter kernels.
#include "gl_fixture.h"

#include "scene/builtin_scenes.h"

#include <glm/geometric.hpp>

namespace shadowlab::test {
namespace {

class BiasAndSampling : public GlTest {};

// Share of sample points on the grazing plane's light side (never in the box's shadow) that come out shadowed.
double falseShadowOnGrazingPlane(const View& view, int litAbove = 128) {
    const glm::dvec3 n(builtin::grazingPlaneNormal());
    const glm::dvec3 l = glm::normalize(glm::dvec3(builtin::kDefaultLightDir));
    // Tangent frame: t1 along the light's direction projected on the plane (shadows fall toward +t1).
    const glm::dvec3 t1 = glm::normalize(l - glm::dot(l, n) * n);
    const glm::dvec3 t2 = glm::cross(n, t1);
    int shadowed = 0, total = 0;
    for (double a = -14.0; a <= -2.0; a += 0.25)
        for (double b = -8.0; b <= 8.0; b += 0.25) {
            const int red = view.redAt(a * t1 + b * t2);
            if (red < 0) continue;
            ++total;
            shadowed += red < litAbove;
        }
    EXPECT_GT(total, 500) << "too few plane points on screen";
    return total ? double(shadowed) / total : 0.0;
}

TEST_F(BiasAndSampling, AcnePresetShowsFalseShadowOnTheGrazingPlaneAndDefaultDoesNot) {
    Renderer renderer;
    const Scene scene = loadBuiltin("grazing");
    Settings acne = loadShippedPreset("acne");
    acne.view = ViewMode::Shadow;
    Settings def = loadShippedPreset("default");
    def.view = ViewMode::Shadow;
    const View acneView = renderView(renderer, scene, acne, 640, 480);
    const View defaultView = renderView(renderer, scene, def, 640, 480);
    saveView(acneView, "grazing-acne");
    saveView(defaultView, "grazing-default");
    const double acneShare = falseShadowOnGrazingPlane(acneView);
    const double defaultShare = falseShadowOnGrazingPlane(defaultView);
    EXPECT_GT(acneShare, 0.05) << "zero bias at 80 degrees must show acne";
    EXPECT_LT(defaultShare, 0.001) << "the default bias must remove it";
}

TEST_F(BiasAndSampling, EveryShippedPresetButAcneLeavesTheGrazingPlaneFullyLit) {
    // Not even partial darkening (a wide kernel reads texels further away and needs more slope bias).
    Renderer renderer;
    const Scene scene = loadBuiltin("grazing");
    for (const char* name : {"default", "soft", "pcf-wide", "peter-panning"}) {
        Settings s = loadShippedPreset(name);
        s.view = ViewMode::Shadow;
        const View view = renderView(renderer, scene, s, 640, 480);
        EXPECT_LT(falseShadowOnGrazingPlane(view, 250), 0.01) << name;
    }
}

// A light straight down over the textbook scene with a manual 8-unit ortho volume: the map covers x,z in [-4,4];
// the floor point (8,0,0) lies outside it, and wrapping brings it back onto the cube at x=0.
Settings outsideTheMap(AddressMode mode, float borderDepth) {
    Settings s = loadShippedPreset("default");
    s.lights[0].direction = glm::vec3(0.0f, -1.0f, 0.0f);
    s.lights[0].projection.autoFit = false;
    s.lights[0].projection.orthoSize = 8.0f;
    s.lights[0].projection.nearPlane = 0.1f;
    s.lights[0].projection.farPlane = 30.0f;
    s.sampler.addressMode = mode;
    s.sampler.borderDepth = borderDepth;
    s.filter.kind = FilterKind::Point;
    s.view = ViewMode::Shadow;
    s.camera.autoFrame = false;
    s.camera.position = glm::vec3(0.0f, 30.0f, 0.0f);
    s.camera.target = glm::vec3(0.0f);
    return s;
}

TEST_F(BiasAndSampling, EachAddressModeDoesWhatItSaysOutsideTheMap) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    const glm::dvec3 outside(8.0, 0.0, 0.0), inside(2.5, 0.0, 2.5);

    const View border1 = renderView(renderer, scene, outsideTheMap(AddressMode::ClampToBorder, 1.0f), 400, 400);
    EXPECT_GT(border1.meanRedAround(outside, 2), 235.0) << "border depth 1: lit outside";
    EXPECT_GT(border1.meanRedAround(inside, 2), 235.0);

    const View border0 = renderView(renderer, scene, outsideTheMap(AddressMode::ClampToBorder, 0.0f), 400, 400);
    EXPECT_LT(border0.meanRedAround(outside, 2), 20.0) << "border depth 0: shadowed outside";
    EXPECT_GT(border0.meanRedAround(inside, 2), 235.0) << "inside the map the border does not matter";

    const View wrap = renderView(renderer, scene, outsideTheMap(AddressMode::Wrap, 1.0f), 400, 400);
    saveView(wrap, "address-wrap");
    EXPECT_LT(wrap.meanRedAround(outside, 2), 20.0) << "wrap: (8,0,0) reads the cube at (0,0,0)";
    EXPECT_GT(wrap.meanRedAround({8.0, 0.0, 2.5}, 2), 235.0) << "wrap: (8,0,2.5) reads open floor";

    const View clamp = renderView(renderer, scene, outsideTheMap(AddressMode::ClampToEdge, 0.0f), 400, 400);
    EXPECT_GT(clamp.meanRedAround(outside, 2), 235.0) << "clamp to edge: the edge texel is open floor";
}

// Pixels in the shadow view that are neither fully lit nor fully shadowed: the penumbra.
long penumbraPixels(const View& view) {
    return view.countScenePixels([](int red) { return red > 12 && red < 243; });
}

TEST_F(BiasAndSampling, LargerKernelsGiveWiderPenumbrae) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = loadShippedPreset("default");
    s.view = ViewMode::Shadow;
    s.lights[0].shadow.resolution = 512;  // coarse texels: the penumbra is many pixels wide
    long previous = -1;
    for (int kernel : {1, 3, 5, 9}) {
        s.filter.kind = FilterKind::Pcf;
        s.filter.kernel = kernel;
        const View view = renderView(renderer, scene, s, 480, 360);
        const long penumbra = penumbraPixels(view);
        if (kernel == 9) saveView(view, "pcf9");
        EXPECT_GT(penumbra, previous) << "PCF " << kernel << "x" << kernel;
        previous = penumbra;
    }
    s.filter.kind = FilterKind::Point;
    EXPECT_EQ(penumbraPixels(renderView(renderer, scene, s, 480, 360)), 0) << "single-tap compare is binary";
    s.filter.kind = FilterKind::Poisson;
    s.filter.poissonRadius = 1.0f;
    const long poissonSmall = penumbraPixels(renderView(renderer, scene, s, 480, 360));
    s.filter.poissonRadius = 4.0f;
    EXPECT_GT(penumbraPixels(renderView(renderer, scene, s, 480, 360)), poissonSmall);
}

TEST_F(BiasAndSampling, FarTooMuchBiasDetachesShadowsFromThinWalls) {
    Renderer renderer;
    const Scene scene = loadBuiltin("thin-walls");
    const Settings good = topDownShadowView(loadShippedPreset("default"));
    const Settings panning = topDownShadowView(loadShippedPreset("peter-panning"));
    const View goodView = renderView(renderer, scene, good, 640, 480);
    const View panView = renderView(renderer, scene, panning, 640, 480);
    saveView(panView, "thin-walls-peter-panning");
    saveView(goodView, "thin-walls-default");
    // Right at the foot of the middle wall (z = 0, thickness 0.1), on its shadow side (light travels toward -z).
    const glm::dvec3 foot(0.0, 0.0, -0.05 - 0.1);
    EXPECT_LT(goodView.meanRedAround(foot, 0), 60.0) << "the default preset keeps the shadow attached";
    EXPECT_GT(panView.meanRedAround(foot, 0), 200.0) << "far too much bias lets light leak under the wall";
}

}  // namespace
}  // namespace shadowlab::test
