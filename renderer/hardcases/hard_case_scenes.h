#pragma once
// Scenes the cases build in code, made of builtin:textbook's meshes (its 20 x 20 floor facing +y and its 2 x 2 x 2
// cube centred at (0,1,0)) placed by instance transforms: no second copy of the mesh code.
#include "scene/scene.h"

#include <glm/vec3.hpp>

namespace shadowlab::hardcases {

// An empty scene holding textbook's floor (mesh 0) and cube (mesh 1) and their materials, with no instances.
Scene meshKit(const char* name);
// Instances of the kit: the floor scaled to `size` x `size` at height y; a box of `size` with its centre at `center`.
void addFloor(Scene& scene, float size, float y = 0.0f);
// mirrorX: scaled by -1 along x (a negative determinant: its triangles wind the other way in world space).
void addBox(Scene& scene, const glm::vec3& center, const glm::vec3& size, bool mirrorX = false);

// About 170 units across: a 170 x 170 floor and a grid of 8 x 8 buildings of 4..24 units height (case 3, 17).
Scene cityScene();
// `scene` with every instance moved by `offset` (bounds recomputed).
Scene translated(const Scene& scene, const glm::vec3& offset);
// `scene` with every instance scaled by `factor` about the origin (bounds recomputed).
Scene scaled(const Scene& scene, float factor);

}  // namespace shadowlab::hardcases
