#include "scene/gltf_primitives.h"

#include "scene/gltf_accessors.h"
#include "scene/gltf_geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

namespace shadowlab::gltf {

std::string meshLabel(const tg::Model& model, int meshIndex) {
    const std::string& n = model.meshes[meshIndex].name;
    return "mesh " + str(meshIndex) + (n.empty() ? "" : " '" + n + "'");
}

std::optional<Mesh> convertPrimitive(const tg::Model& model, int meshIndex, int primIndex, const Warn& warn,
                                     PrimitiveTally& tally) {
    const tg::Mesh& gm = model.meshes[std::size_t(meshIndex)];
    const tg::Primitive& p = gm.primitives[std::size_t(primIndex)];
    const std::string where = meshLabel(model, meshIndex) + " primitive " + str(primIndex);
    auto skip = [&](const std::string& why) -> std::optional<Mesh> {
        warn(where + ": " + why + "; primitive skipped");
        return std::nullopt;
    };

    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
        return skip("mode " + str(mode) + " is points or lines, not triangles");
    const auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) return skip("no POSITION attribute");
    if (p.extensions.count("KHR_draco_mesh_compression") && pos->second >= 0 &&
        pos->second < int(model.accessors.size()) && model.accessors[std::size_t(pos->second)].bufferView < 0)
        return skip("Draco-compressed geometry is not supported");

    // What this primitive decodes to (positions, normals, uvs: 32 bytes a vertex; indices read and rebuilt: 8 each),
    // counted before anything is allocated.
    auto countOf = [&](int accessor) {
        return accessor >= 0 && accessor < int(model.accessors.size()) ? model.accessors[std::size_t(accessor)].count
                                                                        : std::size_t(0);
    };
    const std::size_t vertices = countOf(pos->second);
    const std::size_t indexCount = p.indices >= 0 ? countOf(p.indices) : vertices;
    const bool countable = vertices <= kMaxDecodedBytes / 32 && indexCount <= kMaxDecodedBytes / 8;
    if (tally.budget && !(countable && tally.budget->take(vertices * 32 + indexCount * 8))) {
        tally.budget->exceeded = true;
        return skip("its " + str(vertices) + " vertices and " + str(indexCount) + " indices pass the scene's " +
                    str(kMaxDecodedBytes >> 20) + " MiB decode limit");
    }

    std::string err;
    std::vector<float> raw;
    if (!readFloats(model, pos->second, TINYGLTF_TYPE_VEC3, raw, err)) return skip("POSITION: " + err);
    const std::size_t n = raw.size() / 3;
    if (n == 0) return skip("no vertices");
    if (n >= UINT32_MAX) return skip("too many vertices");

    std::vector<std::uint32_t> idx;
    if (p.indices >= 0) {
        if (!readIndices(model, p.indices, idx, err)) return skip("indices: " + err);
        const auto bad = std::count_if(idx.begin(), idx.end(), [&](std::uint32_t i) { return i >= n; });
        if (bad > 0)
            return skip(str(std::size_t(bad)) + " of " + str(idx.size()) + " indices are out of range (" + str(n) +
                        " vertices)");
    } else {
        idx.resize(n);
        std::iota(idx.begin(), idx.end(), 0u);
    }
    if (mode == TINYGLTF_MODE_TRIANGLES && idx.size() % 3 != 0)
        warn(where + ": index count " + str(idx.size()) + " is not a multiple of 3; the rest is ignored");

    Mesh mesh;
    mesh.name = gm.name.empty() ? "mesh " + str(meshIndex) : gm.name;
    if (gm.primitives.size() > 1) mesh.name += " #" + str(primIndex);
    mesh.indices = toTriangleList(idx, mode);
    mesh.positions.resize(n);
    std::memcpy(mesh.positions.data(), raw.data(), n * sizeof(glm::vec3));

    if (const auto it = p.attributes.find("NORMAL"); it != p.attributes.end()) {
        if (!readFloats(model, it->second, TINYGLTF_TYPE_VEC3, raw, err))
            warn(where + ": NORMAL ignored (" + err + ")");
        else if (raw.size() != n * 3)
            warn(where + ": NORMAL has " + str(raw.size() / 3) + " entries for " + str(n) + " vertices; ignored");
        else {
            mesh.normals.resize(n);
            std::memcpy(mesh.normals.data(), raw.data(), n * sizeof(glm::vec3));
        }
    }
    if (const auto it = p.attributes.find("TEXCOORD_0"); it != p.attributes.end()) {
        if (!readFloats(model, it->second, TINYGLTF_TYPE_VEC2, raw, err))
            warn(where + ": TEXCOORD_0 ignored (" + err + ")");
        else if (raw.size() != n * 2)
            warn(where + ": TEXCOORD_0 has " + str(raw.size() / 2) + " entries for " + str(n) + " vertices; ignored");
        else {
            mesh.uvs.resize(n);
            std::memcpy(mesh.uvs.data(), raw.data(), n * sizeof(glm::vec2));
        }
    }

    const std::size_t dropped = dropNonFiniteTriangles(mesh);
    if (mesh.indices.empty())
        return skip(dropped ? "all " + str(dropped) + " triangles have non-finite (inf/NaN) positions" : "no triangles");
    if (dropped) warn(where + ": " + str(dropped) + " triangles with non-finite (inf/NaN) positions dropped");
    tally.zeroAreaTriangles += countZeroArea(mesh);

    if (mesh.normals.empty()) {
        mesh.normals = smoothNormals(mesh);
    } else {
        std::vector<glm::vec3> fallback;
        std::size_t repaired = 0;
        for (std::size_t i = 0; i < n && i < mesh.normals.size(); ++i) {
            glm::vec3& v = mesh.normals[i];
            const float len = glm::length(v);
            if (finite(v) && len > 1e-12f && std::isfinite(len)) {
                v /= len;
                continue;
            }
            if (fallback.empty()) fallback = smoothNormals(mesh);
            v = fallback[i];
            ++repaired;
        }
        if (repaired) warn(where + ": " + str(repaired) + " zero or non-finite normals recomputed");
    }
    std::size_t badUv = 0;
    for (glm::vec2& uv : mesh.uvs) {
        if (std::isfinite(uv.x) && std::isfinite(uv.y)) continue;
        uv = glm::vec2(0.0f);
        ++badUv;
    }
    if (badUv) warn(where + ": " + str(badUv) + " non-finite texture coordinates set to 0");

    if (p.material >= int(model.materials.size())) warn(where + ": material " + str(p.material) + " does not exist");
    mesh.material = p.material < int(model.materials.size()) ? std::max(p.material, -1) : -1;
    if (!p.targets.empty() && !tally.morphWarned) {
        tally.morphWarned = true;
        warn("morph targets are ignored: meshes are drawn in their base shape");
    }
    return mesh;
}

}  // namespace shadowlab::gltf
