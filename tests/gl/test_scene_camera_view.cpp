// The camera camera.sceneCamera gives (frame/camera.h) on tests/data/scenes/sky_box_city.gltf: the file's position,
// direction, fov or orthographic height and near/far, with the view's aspect; an index the scene lacks is an error
// naming the key.
#include "frame/camera.h"
#include "scene/gltf_loader.h"
#include "settings/settings_fields.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <string>

using namespace shadowlab;

namespace {

Scene loadCity() {
    SceneLoadResult r = loadGltfScene(std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/sky_box_city.gltf");
    EXPECT_TRUE(r.scene) << r.error;
    return r.scene ? std::move(*r.scene) : Scene{};
}

}  // namespace

TEST(SceneCameras, SceneCameraKeyGivesTheFileCameraWithTheViewsAspect) {
    const Scene scene = loadCity();
    Settings s;
    EXPECT_EQ(s.camera.sceneCamera, -1);  // old presets: the free camera
    ASSERT_EQ(applySettingOverride(s, "camera.sceneCamera=0"), "");
    EXPECT_EQ(sceneCameraError(s.camera, scene), "");
    const Camera c = cameraFor(s.camera, scene, 2.0);
    EXPECT_NEAR(glm::length(c.position - glm::dvec3(0.0, 6.0, 16.0)), 0.0, 1e-9);
    const glm::dvec3 forward = glm::normalize(c.target - c.position);
    EXPECT_NEAR(glm::dot(forward, scene.cameras[0].forward), 1.0, 1e-9);
    EXPECT_NEAR(c.fovYDeg, glm::degrees(0.9), 1e-9);
    EXPECT_NEAR(c.nearPlane, 0.1, 1e-12);
    EXPECT_NEAR(c.farPlane, 200.0, 1e-12);
    // The aspect is the caller's (the file says 1.0): x is scaled by 1 / (aspect tan(fov / 2)).
    EXPECT_NEAR(c.projection(2.0)[0][0], 1.0 / (2.0 * std::tan(0.45)), 1e-9);

    // Orthographic: half height = ymag; the width follows the aspect.
    s.camera.sceneCamera = 1;
    const Camera top = cameraFor(s.camera, scene, 2.0);
    EXPECT_NEAR(top.orthoHalfHeight, 12.0, 1e-12);
    EXPECT_NEAR(top.projection(2.0)[1][1], 1.0 / 12.0, 1e-12);
    EXPECT_NEAR(top.projection(2.0)[0][0], 1.0 / 24.0, 1e-12);
    EXPECT_NEAR(top.worldPerPixel(5.0, 100), 0.24, 1e-12);

    // No zfar: the far plane reaches past the whole scene.
    s.camera.sceneCamera = 2;
    const Camera infinite = cameraFor(s.camera, scene, 1.0);
    EXPECT_GT(infinite.farPlane, glm::length(infinite.position - glm::dvec3(scene.bounds.center())) +
                                     double(scene.bounds.radius()));

    // An index beyond the scene's cameras: an error naming the key, the index and what there is.
    s.camera.sceneCamera = 7;
    const std::string error = sceneCameraError(s.camera, scene);
    EXPECT_NE(error.find("camera.sceneCamera: 7 is not a camera of scene sky_box_city"), std::string::npos) << error;
    EXPECT_NE(error.find("0..2"), std::string::npos) << error;
    EXPECT_NE(error.find("'Street'"), std::string::npos) << error;
    // The key's own range: -1 and up.
    EXPECT_NE(applySettingOverride(s, "camera.sceneCamera=-2"), "");
}

