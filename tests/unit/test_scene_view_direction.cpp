// The auto-framed camera's side: a single-sided board is shown from its front; symmetric scenes keep the default.
#include "scene/builtin_scenes.h"
#include "scene/scene.h"

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace shadowlab {
namespace {

// A 4x2 board in the plane z = 0, facing +z (counter-clockwise seen from +z).
Scene board(const glm::mat4& transform) {
    Scene scene;
    Mesh m;
    m.positions = {{-2, 0, 0}, {2, 0, 0}, {2, 2, 0}, {-2, 2, 0}};
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes.push_back(m);
    scene.instances.push_back({0, transform});
    scene.computeBounds();
    return scene;
}

TEST(SceneViewDirection, SingleSidedBoardIsSeenFromItsFront) {
    EXPECT_GT(board(glm::mat4(1.0f)).viewDirection.z, 0.3f);
    const glm::mat4 turned = glm::rotate(glm::mat4(1.0f), glm::radians(180.0f), glm::vec3(0, 1, 0));
    EXPECT_LT(board(turned).viewDirection.z, -0.3f);
    // A mirrored instance reverses winding: the mirrored board (scale z by -1 keeps it in z = 0) faces -z.
    const glm::mat4 mirrored = glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, -1));
    EXPECT_LT(board(mirrored).viewDirection.z, -0.3f);
}

TEST(SceneViewDirection, ViewDirectionIsUnitAndLooksDownOnTheScene) {
    for (const std::string& name : builtinSceneNames()) {
        const std::optional<Scene> scene = makeBuiltinScene(name);
        ASSERT_TRUE(scene.has_value());
        EXPECT_NEAR(glm::length(scene->viewDirection), 1.0f, 1e-4f) << name;
        EXPECT_GT(scene->viewDirection.y, 0.3f) << name;
    }
    EXPECT_GT(glm::dot(makeBuiltinScene("textbook")->viewDirection, Scene::kDefaultViewDirection), 0.9999f);
}

}  // namespace
}  // namespace shadowlab
