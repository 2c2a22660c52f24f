#pragma once
// Each cascade's colour (0 = nearest the camera): the cascade tint view (the main shader's VIEW_CASCADES, which gets
// the list as the CASCADE_TINTS define), the cascades' frusta over the viewport and the editor's lists use this one
// list, so a colour means the same cascade everywhere.
#include <glm/vec3.hpp>

#include <array>
#include <string>

namespace shadowlab {

inline constexpr std::array<glm::vec3, 4> kCascadeTints = {
    glm::vec3(1.0f, 0.25f, 0.2f), glm::vec3(0.25f, 0.9f, 0.3f), glm::vec3(0.25f, 0.45f, 1.0f),
    glm::vec3(1.0f, 0.9f, 0.2f)};

// Cascade `index`'s colour (an index past the list wraps around).
glm::vec3 cascadeTint(int index);

// "CASCADE_TINTS vec3[4](vec3(1.0, 0.25, 0.2), ...)": the list as a GLSL array constructor, for a shader's #defines.
std::string cascadeTintsDefine();

}  // namespace shadowlab
