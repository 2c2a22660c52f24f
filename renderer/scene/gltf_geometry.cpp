#include "scene/gltf_geometry.h"

#include "scene/gltf_common.h"

#include <tiny_gltf.h>  // TINYGLTF_MODE_*

#include <glm/geometric.hpp>

#include <cmath>
#include <cstddef>

namespace shadowlab::gltf {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::vector<std::uint32_t> toTriangleList(const std::vector<std::uint32_t>& idx, int mode) {
    std::vector<std::uint32_t> tri;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        tri.assign(idx.begin(), idx.begin() + std::ptrdiff_t(idx.size() / 3 * 3));
    } else if (idx.size() >= 3) {
        tri.reserve((idx.size() - 2) * 3);
        for (std::size_t i = 0; i + 2 < idx.size(); ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
                tri.insert(tri.end(), {idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]});
            else
                tri.insert(tri.end(), {idx[i + 1], idx[i + 2], idx[0]});
        }
    }
    return tri;
}

std::size_t dropNonFiniteTriangles(Mesh& mesh) {
    std::vector<char> bad(mesh.positions.size());
    bool any = false;
    for (std::size_t i = 0; i < bad.size(); ++i) any |= (bad[i] = !finite(mesh.positions[i]));
    if (!any) return 0;
    std::vector<std::uint32_t> kept;
    kept.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t* tri = &mesh.indices[t];
        if (!bad[tri[0]] && !bad[tri[1]] && !bad[tri[2]]) kept.insert(kept.end(), tri, tri + 3);
    }
    const std::size_t dropped = (mesh.indices.size() - kept.size()) / 3;
    // Compact: keep referenced vertices only, in their original order.
    std::vector<std::uint32_t> remap(mesh.positions.size(), UINT32_MAX);
    for (std::uint32_t v : kept) remap[v] = 0;
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < remap.size(); ++v) {
        if (remap[v] == UINT32_MAX) continue;
        remap[v] = next;
        mesh.positions[next] = mesh.positions[v];
        if (!mesh.normals.empty()) mesh.normals[next] = mesh.normals[v];
        if (!mesh.uvs.empty()) mesh.uvs[next] = mesh.uvs[v];
        ++next;
    }
    mesh.positions.resize(next);
    if (!mesh.normals.empty()) mesh.normals.resize(next);
    if (!mesh.uvs.empty()) mesh.uvs.resize(next);
    for (std::uint32_t& v : kept) v = remap[v];
    mesh.indices = std::move(kept);
    return dropped;
}

std::vector<glm::vec3> smoothNormals(const Mesh& mesh) {
    std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const glm::dvec3 pa(mesh.positions[a]);
        const glm::dvec3 n = glm::cross(glm::dvec3(mesh.positions[b]) - pa, glm::dvec3(mesh.positions[c]) - pa);
        sum[a] += n;
        sum[b] += n;
        sum[c] += n;
    }
    std::vector<glm::vec3> normals(sum.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
        const double len = glm::length(sum[i]);
        normals[i] = len > 0.0 && std::isfinite(len) ? glm::vec3(sum[i] / len) : glm::vec3(0, 1, 0);
    }
    return normals;
}

std::size_t countZeroArea(const Mesh& mesh) {
    std::size_t n = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a(mesh.positions[mesh.indices[t]]);
        const glm::dvec3 e1 = glm::dvec3(mesh.positions[mesh.indices[t + 1]]) - a;
        const glm::dvec3 e2 = glm::dvec3(mesh.positions[mesh.indices[t + 2]]) - a;
        if (glm::cross(e1, e2) == glm::dvec3(0.0)) ++n;
    }
    return n;
}

bool fitsFloat(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!fitsFloat(m[c][r])) return false;
    return true;
}
}  // namespace shadowlab::gltf
