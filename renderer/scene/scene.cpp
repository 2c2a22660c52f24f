#include "scene/scene.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

bool Instance::mirrored() const { return glm::determinant(glm::mat3(transform)) < 0.0f; }

NodeFrame nodeFrame(const glm::dmat4& world) {
    NodeFrame frame;
    frame.position = glm::dvec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 forward = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
    const double length = glm::length(forward);
    if (length > 1e-12 && std::isfinite(length)) frame.forward = forward / length;
    return frame;
}

std::string nodePathSegment(const std::string& name, int gltfIndex) {
    if (name.empty()) return "#" + std::to_string(gltfIndex);
    std::string out = name.front() == '#' ? "\\" : "";  // never read as an unnamed node's "#<index>"
    for (char c : name) {
        if (c == '/' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}

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

namespace {

// Projected front-facing area of every triangle toward each candidate direction (double-sided faces count from
// both sides); the default direction wins ties so symmetric scenes keep the familiar view.
glm::vec3 chooseViewDirection(const Scene& scene) {
    constexpr int kCandidates = 8;
    glm::vec3 candidates[kCandidates];
    const glm::vec3 d = Scene::kDefaultViewDirection;
    for (int i = 0; i < kCandidates; ++i) {
        const float angle = float(i) * 6.2831853f / kCandidates;  // rotate the default view about +y
        const float c = std::cos(angle), s = std::sin(angle);
        candidates[i] = glm::normalize(glm::vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z));
    }
    double score[kCandidates] = {};
    for (const Instance& inst : scene.instances) {
        const Mesh& mesh = scene.meshes[std::size_t(inst.mesh)];
        const Material* material = scene.materialOf(mesh);
        const bool twoSided = material && material->doubleSided;
        const float winding = inst.mirrored() ? -1.0f : 1.0f;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const glm::vec3 a(inst.transform * glm::vec4(mesh.positions[mesh.indices[t]], 1.0f));
            const glm::vec3 b(inst.transform * glm::vec4(mesh.positions[mesh.indices[t + 1]], 1.0f));
            const glm::vec3 c(inst.transform * glm::vec4(mesh.positions[mesh.indices[t + 2]], 1.0f));
            const glm::vec3 areaNormal = winding * 0.5f * glm::cross(b - a, c - a);
            if (!std::isfinite(areaNormal.x) || !std::isfinite(areaNormal.y) || !std::isfinite(areaNormal.z)) continue;
            for (int i = 0; i < kCandidates; ++i) {
                const float facing = glm::dot(areaNormal, candidates[i]);
                score[i] += double(twoSided ? std::abs(facing) : std::max(facing, 0.0f));
            }
        }
    }
    int best = 0;
    for (int i = 1; i < kCandidates; ++i)
        if (score[i] > score[best] * 1.02) best = i;
    return candidates[best];
}

}  // namespace

void Scene::computeBounds() {
    bounds = Bounds{};
    for (const Instance& inst : instances) {
        const Mesh& mesh = meshes[inst.mesh];
        for (const glm::vec3& p : mesh.positions) bounds.extend(glm::vec3(inst.transform * glm::vec4(p, 1.0f)));
    }
    viewDirection = chooseViewDirection(*this);
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
        if (inst.node < -1 || inst.node >= int(nodes.size())) return "instance refers to a missing node";
        for (int c = 0; c < 4; ++c)
            if (!finite3(glm::vec3(inst.transform[c])) || !std::isfinite(inst.transform[c][3]))
                return "instance transform is not finite";
    }
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        const SceneNode& node = nodes[n];
        if (node.parent < -1 || node.parent >= int(n)) return "node '" + node.path + "': its parent does not precede it";
        for (int child : node.children)
            if (child <= int(n) || child >= int(nodes.size()) || nodes[std::size_t(child)].parent != int(n))
                return "node '" + node.path + "': a child that does not name it as its parent";
    }
    for (const SceneCamera& camera : cameras)
        if (!finite3(glm::vec3(camera.position)) || std::abs(glm::length(camera.forward) - 1.0) > 1e-6)
            return "camera '" + camera.name + "': position not finite or direction not unit length";
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
