// The world point under a pixel (frame/surface_pick.h), read back from the view's depth: on the sky-box city seen by
// its orthographic "Top" camera the tower's top and an open patch of ground come back where they are; a pixel that
// shows no surface gives none.
#include "frame/surface_pick.h"
#include "gl_fixture.h"
#include "scene/gltf_loader.h"

namespace shadowlab::test {
namespace {

class SurfacePick : public GlTest {};

TEST_F(SurfacePick, PickedPointsLieOnTheSurfaceShown) {
    SceneLoadResult loaded = loadGltfScene(std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/sky_box_city.gltf");
    ASSERT_TRUE(loaded.scene) << loaded.error;
    const Scene& scene = *loaded.scene;
    Settings s = loadShippedPreset("default");
    s.camera.sceneCamera = 1;  // "Top": orthographic, half height 12, looking straight down from y = 30
    const int width = 320, height = 240;
    Renderer renderer;
    RenderTarget target;
    ASSERT_EQ(target.resize(width, height), "");
    const FrameStats stats = renderer.render(scene, s, cameraFor(s.camera, scene, double(width) / height), target);
    ASSERT_TRUE(stats.ok) << stats.error;

    // The centre shows the tower's top (y = 6) above the origin.
    const std::optional<glm::dvec3> top = pickSurface(target, stats, width / 2, height / 2);
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->y, 6.0, 1e-3);
    EXPECT_NEAR(top->x, 0.0, 0.1);
    EXPECT_NEAR(top->z, 0.0, 0.1);
    // World (5, 0, 5): right of the centre by 5 / 16 of the half width, below it by 5 / 12 of the half height
    // (looking down, the view's up is -z).
    const std::optional<glm::dvec3> ground = pickSurface(target, stats, 160 + 50, 120 + 50);
    ASSERT_TRUE(ground);
    EXPECT_NEAR(ground->y, 0.0, 1e-3);
    EXPECT_NEAR(ground->x, 5.0 + 0.05, 0.1);
    EXPECT_NEAR(ground->z, 5.0 + 0.05, 0.1);
    EXPECT_FALSE(pickSurface(target, stats, -1, 0)) << "outside the view";

    // The background: textbook's auto-framed view leaves its top-left corner empty.
    const Scene textbook = loadBuiltin("textbook");
    Settings t = loadShippedPreset("default");
    const FrameStats framed = renderer.render(textbook, t, cameraFor(t.camera, textbook, double(width) / height), target);
    ASSERT_TRUE(framed.ok) << framed.error;
    EXPECT_FALSE(pickSurface(target, framed, 0, 0));
}

}  // namespace
}  // namespace shadowlab::test
