// Issue 9, observation 3: one rule for single-sided geometry. The main pass and the G-buffer follow glTF (back
// faces of single-sided materials are not drawn, double-sided ones are, mirrored instances flip the winding), so
// what the view shows and what the accuracy meter measures are the same pixels.
#include "accuracy/gbuffer_pass.h"
#include "gl_fixture.h"

#include <glm/ext/matrix_transform.hpp>

namespace shadowlab::test {
namespace {

class SingleSided : public GlTest {};

// A horizontal quad (y = height, |x|, |z| <= half) facing up, or down when `facingDown`.
Mesh horizontalQuad(float height, float half, bool facingDown, int material) {
    Mesh m;
    m.name = facingDown ? "down" : "up";
    m.positions = {{-half, height, -half}, {-half, height, half}, {half, height, half}, {half, height, -half}};
    m.normals.assign(4, glm::vec3(0, facingDown ? -1 : 1, 0));
    m.indices = facingDown ? std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2} : std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3};
    m.material = material;
    return m;
}

Material colored(glm::vec4 color, bool doubleSided) {
    Material m;
    m.baseColorFactor = color;
    m.doubleSided = doubleSided;
    return m;
}

// A grey floor and four red roofs 2 units above it, seen from above (so every roof shows its top side):
//  x=-6: faces down, single-sided            -> its back: not drawn
//  x=-2: faces down, double-sided            -> drawn
//  x=+2: faces up, mirrored (scale y = -1)   -> faces down in the world: not drawn
//  x=+6: faces down, mirrored                -> faces up in the world: drawn
Scene roofs() {
    Scene scene;
    scene.name = "roofs";
    scene.materials = {colored({0.8f, 0.8f, 0.8f, 1.0f}, false), colored({0.9f, 0.1f, 0.1f, 1.0f}, false),
                       colored({0.9f, 0.1f, 0.1f, 1.0f}, true)};
    scene.meshes.push_back(horizontalQuad(0.0f, 10.0f, false, 0));
    scene.meshes.push_back(horizontalQuad(2.0f, 1.5f, true, 1));    // single-sided, faces down
    scene.meshes.push_back(horizontalQuad(2.0f, 1.5f, true, 2));    // double-sided
    scene.meshes.push_back(horizontalQuad(-2.0f, 1.5f, false, 1));  // faces up before the mirror
    const glm::mat4 mirrorY = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, -1.0f, 1.0f));
    auto at = [](float x) { return glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f)); };
    scene.instances = {{0, glm::mat4(1.0f)}, {1, at(-6.0f)}, {2, at(-2.0f)}, {3, at(2.0f) * mirrorY},
                       {1, at(6.0f) * mirrorY * glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -4.0f, 0.0f))}};
    scene.computeBounds();
    return scene;
}

Settings fromAbove() {
    Settings s = topDownShadowView(Settings{});
    s.view = ViewMode::Lit;
    s.lights[0].direction = {0.0f, -1.0f, 0.0f};
    s.camera.position = {0.0, 20.0, 0.1};
    return s;
}

bool isRed(const View& v, const glm::dvec3& world) {
    double px = 0, py = 0;
    if (!projectToPixel(v.stats, world, v.width, v.height, px, py)) return false;
    const int row = v.height - 1 - int(py);
    const std::uint8_t* p = &v.rgba[(std::size_t(row) * std::size_t(v.width) + std::size_t(px)) * 4];
    return p[0] > p[1] + 60;  // the lit red roof, not the grey floor
}

TEST_F(SingleSided, TheMainPassDoesNotDrawBackFacesOfSingleSidedMaterials) {
    Renderer renderer;
    const Scene scene = roofs();
    const View view = renderView(renderer, scene, fromAbove(), 400, 300);
    saveView(view, "single-sided-roofs-from-above");
    EXPECT_FALSE(isRed(view, {-6.0, 2.0, 0.0})) << "a single-sided roof seen from its back shows the floor";
    EXPECT_TRUE(isRed(view, {-2.0, 2.0, 0.0})) << "a double-sided roof is drawn from both sides";
    EXPECT_FALSE(isRed(view, {2.0, 2.0, 0.0})) << "a mirrored up-facing quad faces down in the world";
    EXPECT_TRUE(isRed(view, {6.0, 2.0, 0.0})) << "a mirrored down-facing quad faces up in the world";
    EXPECT_FALSE(isRed(view, {0.0, 2.0, 0.0}));  // the floor between them
}

TEST_F(SingleSided, TheGBufferCoversExactlyWhatTheMainPassDraws) {
    // Oblique, from above and from below the floor: background, front and back faces all in view.
    const Scene scene = roofs();
    for (const glm::dvec3 eye : {glm::dvec3(14.0, 9.0, 12.0), glm::dvec3(-10.0, -6.0, 8.0)}) {
        Settings s = fromAbove();
        s.view = ViewMode::Shadow;  // scene pixels are grey, the background is not
        s.camera.position = eye;
        s.camera.target = {0.0, 1.0, 0.0};
        Renderer renderer;
        const int w = 320, h = 200;
        const View view = renderView(renderer, scene, s, w, h);
        saveView(view, eye.y > 0.0 ? "single-sided-coverage-above" : "single-sided-coverage-below");
        const glm::dvec3 origin = view.stats.renderOrigin;
        GpuScene gpuScene(scene, origin);
        GBufferPass gbuffer;
        SurfaceSamples samples;
        ASSERT_EQ(gbuffer.render(gpuScene, view.stats.cameraViewProjection, w, h, eye - origin, samples), "");
        long drawn = 0, mismatched = 0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const bool inView = view.isGreyScene(std::size_t(h - 1 - y) * std::size_t(w) + std::size_t(x));
                const bool inGBuffer = samples.isSurface(std::size_t(y) * std::size_t(w) + std::size_t(x));
                drawn += inView;
                mismatched += inView != inGBuffer;
            }
        }
        EXPECT_GT(drawn, w * h / 20);
        EXPECT_EQ(mismatched, 0) << "eye " << eye.x << "," << eye.y << "," << eye.z << ": " << drawn << " drawn";
    }
}

}  // namespace
}  // namespace shadowlab::test
