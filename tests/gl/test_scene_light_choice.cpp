// useSceneLights: a glTF's own light replaces the settings' light. (The hard cases of ../shared/HARD_CASES.md that
// lived here are the suite `shadowlab hardcases`, renderer/hardcases, run by ctest as hardcases_quick.)
#include "gl_fixture.h"

#include "scene/builtin_scenes.h"

namespace shadowlab::test {
namespace {

class SceneLightChoice : public GlTest {};

TEST_F(SceneLightChoice, SceneLightFromGltfIsUsedWhenAsked) {
    Renderer renderer;
    Scene scene = loadBuiltin("textbook");
    SceneLight sun;
    sun.type = SceneLightType::Directional;
    sun.direction = glm::vec3(0.4f, -1.0f, 0.3f);  // the mirror image of the default: shadows fall to +x, +z
    scene.lights.push_back(sun);
    Settings s = topDownShadowView(loadShippedPreset("default"));
    s.useSceneLights = true;
    const View view = renderView(renderer, scene, s, 320, 320);
    EXPECT_LT(view.meanRedAround({1.4, 0.0, 1.3}, 2), 20.0) << "shadow on the +x,+z side";
    EXPECT_GT(view.meanRedAround({-1.4, 0.0, -1.3}, 2), 235.0) << "the default light's shadow side is lit";
}

}  // namespace
}  // namespace shadowlab::test
