// Rendering checked against positions whose shadow can be computed by hand (top-down camera, shadow-factor view).
#include "gl_fixture.h"

#include "scene/builtin_scenes.h"

#include <glm/geometric.hpp>

namespace shadowlab::test {
namespace {

class ShadowsByHand : public GlTest {};

TEST_F(ShadowsByHand, PointInTheCubesShadowIsDarkAndOpenFloorIsLit) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    const View view = renderView(renderer, scene, topDownShadowView(loadShippedPreset("default")), 480, 480);
    saveView(view, "textbook-shadow-top");
    // Light travels along (-0.4,-1,-0.3): the cube's top face (y=2) throws its shadow 0.8 along -x, 0.6 along -z.
    EXPECT_LT(view.meanRedAround({-1.4, 0.0, -1.3}, 2), 20.0) << "floor beside the cube, inside its shadow";
    EXPECT_GT(view.meanRedAround({5.0, 0.0, 5.0}, 2), 235.0) << "open floor";
    EXPECT_GT(view.meanRedAround({1.5, 0.0, 1.5}, 2), 235.0) << "floor on the lit side of the cube";
    // The floating box (bottom at 2.75) casts a detached shadow centred ~3 units down-light of it.
    const glm::dvec3 boxShadow = glm::dvec3(builtin::kFloatingBoxCenter) + 3.0 * glm::dvec3(-0.4, -1.0, -0.3);
    EXPECT_LT(view.meanRedAround({boxShadow.x, 0.0, boxShadow.z}, 1), 20.0) << "the floating box's shadow";
}

TEST_F(ShadowsByHand, LitViewDarkensShadowedFloor) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = topDownShadowView(loadShippedPreset("default"));
    s.view = ViewMode::Lit;
    const View view = renderView(renderer, scene, s, 480, 480);
    saveView(view, "textbook-lit-top");
    EXPECT_LT(view.meanRedAround({-1.4, 0.0, -1.3}, 2) + 60.0, view.meanRedAround({5.0, 0.0, 5.0}, 2));
}

TEST_F(ShadowsByHand, AlphaMaskedFenceLetsLightThroughItsGaps) {
    Renderer renderer;
    const Scene scene = loadBuiltin("fence");
    Settings s = topDownShadowView(loadShippedPreset("default"));
    s.lights[0].direction = glm::vec3(0.0f, -1.0f, -0.8f);  // the fence (plane z=0) casts onto the floor at z < 0
    const View view = renderView(renderer, scene, s, 640, 640);
    saveView(view, "fence-shadow-top");
    const glm::vec3 lightDir = glm::normalize(s.lights[0].direction);
    int litChecked = 0, shadowChecked = 0;
    for (float x = -3.9f; x <= 3.9f; x += 0.05f) {
        for (float z : {-0.6f, -1.0f, -2.2f}) {
            const glm::vec3 p(x, 0.0f, z);
            // Only points whose neighbourhood (±0.12) agrees: a texel or two from an edge may go either way.
            const bool shadowed = builtin::fenceShadowsPoint(p, lightDir);
            if (builtin::fenceShadowsPoint(p + glm::vec3(0.12f, 0, 0), lightDir) != shadowed ||
                builtin::fenceShadowsPoint(p - glm::vec3(0.12f, 0, 0), lightDir) != shadowed ||
                builtin::fenceShadowsPoint(p + glm::vec3(0, 0, 0.12f), lightDir) != shadowed ||
                builtin::fenceShadowsPoint(p - glm::vec3(0, 0, 0.12f), lightDir) != shadowed)
                continue;
            const int red = view.redAt(p);
            ASSERT_GE(red, 0);
            if (shadowed) {
                EXPECT_LT(red, 40) << "behind a slat at x=" << x << " z=" << z;
                ++shadowChecked;
            } else {
                EXPECT_GT(red, 215) << "through a gap at x=" << x << " z=" << z;
                ++litChecked;
            }
        }
    }
    EXPECT_GT(litChecked, 40);
    EXPECT_GT(shadowChecked, 40);
}

TEST_F(ShadowsByHand, ChangingTheAlphaCutoffMovesTheShadow) {
    Renderer renderer;
    Scene scene = loadBuiltin("fence");
    Settings s = topDownShadowView(loadShippedPreset("default"));
    s.lights[0].direction = glm::vec3(0.0f, -1.0f, -0.8f);
    const View before = renderView(renderer, scene, s, 320, 320);
    for (Material& m : scene.materials)
        if (m.alphaMode == AlphaMode::Mask) m.alphaCutoff = 1.5f;  // nothing passes: no shadow at all
    const View after = renderView(renderer, scene, s, 320, 320);
    EXPECT_TRUE(after.stats.shadowPass.ran) << "a cutoff change must re-render the shadow map";
    const auto dark = [](int red) { return red < 128; };
    const long darkBefore = before.countScenePixels(dark), darkAfter = after.countScenePixels(dark);
    EXPECT_GT(darkBefore, 1000);
    EXPECT_EQ(darkAfter, 0);
}

TEST_F(ShadowsByHand, SpotLightLightsInsideItsConeOnly) {
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = topDownShadowView(loadShippedPreset("default"));
    s.lights[0].type = LightType::Spot;
    s.lights[0].position = glm::vec3(5.0f, 6.0f, 5.0f);
    s.lights[0].direction = glm::vec3(0.0f, -1.0f, 0.0f);
    s.lights[0].spotConeDeg = 120.0f;  // radius on the floor: 6 * tan(60 deg) = 10.4 around (5, 0, 5)
    const View view = renderView(renderer, scene, s, 480, 480);
    saveView(view, "textbook-spot-top");
    EXPECT_GT(view.meanRedAround({5.0, 0.0, 5.0}, 2), 235.0) << "under the spot";
    EXPECT_GT(view.meanRedAround({8.0, 0.0, 2.0}, 2), 235.0) << "inside the cone";
    EXPECT_LT(view.meanRedAround({-7.0, 0.0, -7.0}, 2), 20.0) << "outside the cone";
    // The ray from (-1.5, 0, -1.5) to the light crosses y = 2 at (0.67, 2, 0.67): inside the cube's top face.
    EXPECT_LT(view.meanRedAround({-1.5, 0.0, -1.5}, 1), 20.0) << "the cube's shadow under the spot";
}

}  // namespace
}  // namespace shadowlab::test
