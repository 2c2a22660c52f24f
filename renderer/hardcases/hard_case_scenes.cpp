#include "hardcases/hard_case_scenes.h"

#include "scene/builtin_scenes.h"

#include <glm/ext/matrix_transform.hpp>

#include <stdexcept>

namespace shadowlab::hardcases {

Scene meshKit(const char* name) {
    std::optional<Scene> textbook = makeBuiltinScene("textbook");
    if (!textbook) throw std::runtime_error("builtin:textbook is missing");
    Scene kit;
    kit.name = name;
    kit.materials = textbook->materials;
    kit.meshes = {textbook->meshes[0], textbook->meshes[1]};  // floor, cube
    return kit;
}

void addFloor(Scene& scene, float size, float y) {
    const float s = size / builtin::kFloorSize;
    scene.instances.push_back(
        {0, glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, y, 0.0f}), glm::vec3(s, 1.0f, s))});
    scene.computeBounds();
}

void addBox(Scene& scene, const glm::vec3& center, const glm::vec3& size, bool mirrorX) {
    // The cube is 2 x 2 x 2 around (0, 1, 0): move its centre to the origin, scale, then place.
    const glm::mat4 toOrigin = glm::translate(glm::mat4(1.0f), -builtin::kCubeCenter);
    const glm::vec3 flip(mirrorX ? -1.0f : 1.0f, 1.0f, 1.0f);
    const glm::mat4 scale = glm::scale(glm::mat4(1.0f), flip * size / builtin::kCubeSize);
    scene.instances.push_back({1, glm::translate(glm::mat4(1.0f), center) * scale * toOrigin});
    scene.computeBounds();
}

Scene cityScene() {
    Scene city = meshKit("city");
    addFloor(city, 170.0f);
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
            const float height = 4.0f + float((i * 5 + j * 3) % 11) * 2.0f;
            const glm::vec3 size(12.0f, height, 12.0f);
            addBox(city, {-73.5f + 21.0f * float(i), 0.5f * height, -73.5f + 21.0f * float(j)}, size);
        }
    return city;
}

Scene translated(const Scene& scene, const glm::vec3& offset) {
    Scene moved = scene;
    for (Instance& instance : moved.instances)
        instance.transform = glm::translate(glm::mat4(1.0f), offset) * instance.transform;
    moved.computeBounds();
    return moved;
}

Scene scaled(const Scene& scene, float factor) {
    Scene out = scene;
    for (Instance& instance : out.instances)
        instance.transform = glm::scale(glm::mat4(1.0f), glm::vec3(factor)) * instance.transform;
    out.computeBounds();
    return out;
}

}  // namespace shadowlab::hardcases
