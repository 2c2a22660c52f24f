#include "reference_fixture.h"

#include "gl_fixture.h"
#include "hardcases/hard_case_scenes.h"
#include "image/image_io.h"
#include "light/scene_lights.h"

#include <cmath>
#include <filesystem>

namespace shadowlab::test {

ReferenceView traceReference(const Scene& scene, const Settings& settings, int width, int height) {
    ReferenceView view;
    Renderer renderer;
    RenderTarget target;
    EXPECT_EQ(target.resize(width, height), "");
    const Camera camera = cameraFor(settings.camera, scene, double(width) / height);
    view.stats = renderer.render(scene, settings, camera, target);
    EXPECT_TRUE(view.stats.ok) << view.stats.error;
    const glm::dvec3 origin = view.stats.renderOrigin;
    GpuScene gpuScene(scene, origin);
    GBufferPass gbuffer;
    EXPECT_EQ(gbuffer.render(gpuScene, view.stats.cameraViewProjection, width, height, camera.position - origin,
                             view.samples),
              "");
    view.bvh = std::make_unique<EmbreeScene>(scene, origin);
    view.light = referenceLight(withEffectiveLights(settings, scene).lights[0], origin);
    view.visibility = traceVisibility(*view.bvh, view.samples, view.light, double(scene.bounds.radius()), nullptr);
    return view;
}

std::string saveOverlay(const AccuracyReport& report, const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(SHADOWLAB_TEST_OUTPUT) / "accuracy";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / (name + ".png")).string();
    EXPECT_EQ(writePng(path, report.width, report.height, 4, report.overlayRgba.data(), false), "");
    return path;
}

Settings topDownAt(Settings s, float x, float z, float h) {
    s.camera.autoFrame = false;
    s.camera.position = glm::vec3(x, h, z);
    s.camera.target = glm::vec3(x, 0.0f, z);
    s.camera.fovYDeg = 45.0f;
    return s;
}

Scene contactWallScene() {
    Scene scene = hardcases::meshKit("pcss-contact-wall");
    hardcases::addFloor(scene, 20.0f);
    hardcases::addBox(scene, {0.0f, 2.0f, 0.0f}, {0.4f, 4.0f, 6.0f});
    return scene;
}

Settings atContactWallEdge(Settings s) {
    s = topDownAt(s, 2.5f, 3.0f, 7.0f);
    s.lights[0].direction = {1.0f, -1.0f, 0.0f};
    return s;
}

}  // namespace shadowlab::test
