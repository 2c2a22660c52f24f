#include "scene/scene.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace shadowlab {

bool Instance::mirrored() const { return glm::determinant(glm::mat3(transform)) < 0.0f; }

float Bounds::radius() const { return empty ? 0.0f : 0.5f * glm::length(max - min); }

void Bounds::extend(const glm::vec3& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return;
    if (empty) {
        min = max = p;
        empty = false;
        return;
    }
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Scene::computeBounds() {
    bounds = Bounds{};
    for (const Instance& inst : instances) {
        const Mesh& mesh = meshes[inst.mesh];
        for (const glm::vec3& p : mesh.positions) bounds.extend(glm::vec3(inst.transform * glm::vec4(p, 1.0f)));
    }
}

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const Instance& inst : instances) n += meshes[inst.mesh].triangleCount();
    return n;
}

std::string Scene::invariantError() const {
    auto finite3 = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const Mesh& mesh = meshes[m];
        const std::string where = "mesh " + std::to_string(m) + " '" + mesh.name + "': ";
        const std::size_t n = mesh.positions.size();
        if (mesh.normals.size() != n) return where + "normal count differs from position count";
        if (!mesh.uvs.empty() && mesh.uvs.size() != n) return where + "uv count differs from position count";
        if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) return where + "index count is not a positive multiple of 3";
        for (std::uint32_t i : mesh.indices)
            if (i >= n) return where + "index out of range";
        for (std::size_t v = 0; v < n; ++v) {
            if (!finite3(mesh.positions[v])) return where + "non-finite position";
            if (!finite3(mesh.normals[v]) || std::abs(glm::length(mesh.normals[v]) - 1.0f) > 1e-3f)
                return where + "normal is not unit length";
        }
        for (const glm::vec2& uv : mesh.uvs)
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return where + "non-finite uv";
        if (mesh.material < -1 || mesh.material >= int(materials.size())) return where + "material out of range";
    }
    for (const Material& mat : materials)
        if (mat.baseColorImage < -1 || mat.baseColorImage >= int(images.size()) ||
            (mat.baseColorImage >= 0 && !images[mat.baseColorImage].valid()))
            return "material '" + mat.name + "': invalid base colour image";
    for (const Instance& inst : instances) {
        if (inst.mesh < 0 || inst.mesh >= int(meshes.size())) return "instance refers to a missing mesh";
        for (int c = 0; c < 4; ++c)
            if (!finite3(glm::vec3(inst.transform[c])) || !std::isfinite(inst.transform[c][3]))
                return "instance transform is not finite";
    }
    return {};
}

const Material* Scene::materialOf(const Mesh& mesh) const {
    if (mesh.material < 0 || mesh.material >= int(materials.size())) return nullptr;
    return &materials[mesh.material];
}

bool Scene::hasAlphaMaskedCasters() const {
    for (const Instance& inst : instances) {
        const Material* m = materialOf(meshes[inst.mesh]);
        if (m && m->alphaMode == AlphaMode::Mask) return true;
    }
    return false;
}

}  // namespace shadowlab
