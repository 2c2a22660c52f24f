// Issue 9: the view camera. Observation 6 (a scene 1e6 from the origin must move when the camera moves 1 mm) and
// auto-framing (the subject fills the frame instead of a bounding sphere's share of it).
#include "gl_fixture.h"

#include "scene/builtin_scenes.h"

#include <glm/ext/matrix_transform.hpp>

#include <algorithm>
#include <cstdlib>

namespace shadowlab::test {
namespace {

class CameraView : public GlTest {};

Scene movedBy(Scene scene, const glm::vec3& offset) {
    for (Instance& inst : scene.instances) inst.transform = glm::translate(glm::mat4(1.0f), offset) * inst.transform;
    scene.computeBounds();
    return scene;
}

TEST_F(CameraView, AMillimetreMoveAtAMillionUnitsChangesThePicture) {
    const glm::dvec3 offset(1e6, 0.0, 1e6);
    const Scene scene = movedBy(loadBuiltin("textbook"), glm::vec3(offset));
    // The cube's top front edge, seen from 0.1 units: one pixel there is about 0.35 mm, so 1 mm moves it ~3 pixels.
    const glm::dvec3 edge = offset + glm::dvec3(builtin::kCubeCenter) +
                            glm::dvec3(0.0, 0.5 * builtin::kCubeSize, 0.5 * builtin::kCubeSize);
    Settings s = loadShippedPreset("default");
    s.camera.autoFrame = false;
    s.camera.target = edge;
    s.camera.position = edge + glm::dvec3(0.0, 0.07, 0.07);
    Renderer renderer;
    const View before = renderView(renderer, scene, s, 240, 240);
    s.camera.position.y += 0.001;
    s.camera.target.y += 0.001;
    const View after = renderView(renderer, scene, s, 240, 240);
    saveView(before, "camera-1e6-before");
    saveView(after, "camera-1e6-after-1mm");
    long changed = 0;
    for (std::size_t i = 0; i < before.rgba.size(); i += 4) changed += before.rgba[i] != after.rgba[i];
    // The edge runs across the whole view; moving it ~3 rows changes at least two rows of pixels.
    EXPECT_GE(changed, 2 * 240) << "a float camera at 1e6 has a 6 cm step: 1 mm changes nothing";
    EXPECT_LT(changed, 240 * 240 / 4) << "the picture moved, it did not fall apart";

    // HARD_CASES 3: the same view of the scene at the origin is the same picture (within an edge pixel's rounding).
    const Scene home = loadBuiltin("textbook");
    Settings atHome = s;
    atHome.camera.position -= offset;
    atHome.camera.target -= offset;
    const View there = renderView(renderer, home, atHome, 240, 240);
    long differ = 0;
    for (std::size_t i = 0; i < there.rgba.size(); i += 4) differ += std::abs(int(there.rgba[i]) - int(after.rgba[i])) > 8;
    EXPECT_LT(differ, 240 * 2) << "the view at 1e6 must not depend on where the scene is";
}

// Bounding box of the scene's pixels (shadow view: grey) in a rendered view.
struct PixelBox {
    int minX = 1 << 30, minY = 1 << 30, maxX = -1, maxY = -1;
};
PixelBox scenePixels(const View& v) {
    PixelBox b;
    for (int y = 0; y < v.height; ++y)
        for (int x = 0; x < v.width; ++x)
            if (v.isGreyScene(std::size_t(y) * std::size_t(v.width) + std::size_t(x))) {
                b.minX = std::min(b.minX, x);
                b.maxX = std::max(b.maxX, x);
                b.minY = std::min(b.minY, y);
                b.maxY = std::max(b.maxY, y);
            }
    return b;
}

// A rod 40 long and 0.5 thick: its bounding sphere is 40 wide, its picture could be a thin line in the middle.
Scene rod() {
    Scene scene;
    scene.name = "rod";
    Mesh m;
    m.name = "rod";
    const float hx = 20.0f, h = 0.25f;
    for (int i = 0; i < 8; ++i) m.positions.emplace_back((i & 1) ? hx : -hx, (i & 2) ? h : -h, (i & 4) ? h : -h);
    m.normals.assign(8, glm::vec3(0, 1, 0));
    // Outward CCW faces of the box, as (corner indices) quads.
    const std::uint32_t quads[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    for (const auto& q : quads) m.indices.insert(m.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    scene.meshes.push_back(m);
    scene.instances.push_back({0, glm::mat4(1.0f)});
    scene.computeBounds();
    return scene;
}

TEST_F(CameraView, AutoFrameFillsTheViewAndCutsNothingOff) {
    std::vector<std::pair<std::string, Scene>> scenes;
    // A scene with its own viewpoint (builtin:city) is auto-framed from it, not whole (test_city_scene.cpp).
    for (const std::string& name : builtinSceneNames())
        if (Scene scene = loadBuiltin(name); !scene.viewpoint) scenes.emplace_back(name, std::move(scene));
    scenes.emplace_back("rod", rod());
    Renderer renderer;
    for (const auto& [name, scene] : scenes) {
        for (const auto& [w, h] : {std::pair{320, 180}, std::pair{160, 320}}) {
            SCOPED_TRACE(name + " " + std::to_string(w) + "x" + std::to_string(h));
            Settings s = loadShippedPreset("default");
            s.view = ViewMode::Shadow;
            const View view = renderView(renderer, scene, s, w, h);
            saveView(view, "autoframe-" + name + "-" + std::to_string(w) + "x" + std::to_string(h));
            const PixelBox box = scenePixels(view);
            ASSERT_GE(box.maxX, 0) << "nothing drawn";
            // Nothing cut off: the subject does not touch the frame's edges.
            EXPECT_GT(box.minX, 0);
            EXPECT_GT(box.minY, 0);
            EXPECT_LT(box.maxX, w - 1);
            EXPECT_LT(box.maxY, h - 1);
            // It fills the limiting dimension (kAutoFrameFill = 90 %; rasterization and culled faces lose a little).
            const double fillX = double(box.maxX - box.minX + 1) / w, fillY = double(box.maxY - box.minY + 1) / h;
            EXPECT_GT(std::max(fillX, fillY), 0.8) << fillX << " x " << fillY;
        }
    }
}

}  // namespace
}  // namespace shadowlab::test
