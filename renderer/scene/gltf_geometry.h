#pragma once
// Geometry repair for imported primitives: triangle lists from strips and fans, dropping non-finite triangles,
// recomputing normals, counting degenerate triangles. Keeps inf/NaN away from bounds, light fitting and the GPU.
#include "scene/scene.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace shadowlab::gltf {

bool finite(const glm::vec3& v);
// Every entry converts to float without overflow: a transform that can become a glm::mat4.
bool fitsFloat(const glm::dmat4& m);

// Triangle list from TRIANGLES / TRIANGLE_STRIP / TRIANGLE_FAN indices (glTF 2.0 spec, 3.7.2.1).
std::vector<std::uint32_t> toTriangleList(const std::vector<std::uint32_t>& idx, int mode);

// Drops triangles that use a non-finite position (BoxWithInfinites.glb), then the vertices no triangle uses, so no
// inf/NaN reaches bounds, light fitting or the GPU. Returns the number of triangles dropped.
std::size_t dropNonFiniteTriangles(Mesh& mesh);

// Area-weighted vertex normals (the face cross product is twice the area); (0,1,0) where no face contributes.
std::vector<glm::vec3> smoothNormals(const Mesh& mesh);

// Triangles whose edges are parallel or zero (kept: they cast no shadow, but the count is reported).
std::size_t countZeroArea(const Mesh& mesh);

}  // namespace shadowlab::gltf
