#pragma once
// One glTF mesh primitive -> one Scene Mesh: positions, indices as a triangle list, normals and TEXCOORD_0, repaired
// (non-finite triangles dropped, bad normals recomputed, bad UVs zeroed) or skipped with a warning saying why.
#include "scene/gltf_common.h"
#include "scene/scene.h"

#include <cstddef>
#include <optional>
#include <string>

namespace shadowlab::gltf {

// What convertPrimitive reports once for the whole file rather than per primitive.
struct PrimitiveTally {
    std::size_t zeroAreaTriangles = 0;  // kept, summed into one warning at the end
    bool morphWarned = false;           // morph targets are ignored: warn on the first one only
    DecodeBudget* budget = nullptr;     // the scene's decode limit, shared with the buffer reads
};

// "mesh N 'name'" for messages.
std::string meshLabel(const tg::Model& model, int meshIndex);

// Primitive `primIndex` of mesh `meshIndex` (both valid), or nullopt (warned) when it has no usable triangles.
std::optional<Mesh> convertPrimitive(const tg::Model& model, int meshIndex, int primIndex, const Warn& warn,
                                     PrimitiveTally& tally);

}  // namespace shadowlab::gltf
