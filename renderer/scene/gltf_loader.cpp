#include "scene/gltf_loader.h"

// The top-level flow: read the file with tinygltf, check its required extensions, import materials, walk the node
// graph from the scene's roots (cycles, depth and blow-up cut) and instance each node's mesh primitives under its
// world transform. The parts live in gltf_accessors, gltf_geometry, gltf_primitives, gltf_images, gltf_materials,
// gltf_lights and gltf_extensions.
#include "scene/gltf_common.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_geometry.h"
#include "scene/gltf_images.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_primitives.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <optional>

namespace shadowlab {
namespace {

using namespace gltf;

constexpr int kMaxNodeDepth = 512;                  // deeper than any real hierarchy: a broken file
constexpr std::size_t kMaxNodeVisits = 2'000'000;   // a node shared by many parents can explode combinatorially
constexpr std::size_t kMaxWarnings = 100;           // keep the list readable on badly broken files

class Loader {
public:
    Loader(const tg::Model& model, const EncodedImages& images) : model_(model), images_(images) {
        meshCache_.resize(model.meshes.size());
        onPath_.assign(model.nodes.size(), 0);
    }

    void warn(const std::string& message) {
        if (scene_.warnings.size() < kMaxWarnings)
            scene_.warnings.push_back(message);
        else
            ++suppressedWarnings_;
    }

    // The scene, or nullopt with `error` set.
    std::optional<Scene> run(std::string& error);

private:
    const std::vector<int>& meshPrimitives(int meshIndex);
    std::vector<int> rootNodes();
    void visit(int index, const glm::dmat4& parent, int depth);
    glm::dmat4 localMatrix(int index);

    const tg::Model& model_;
    const EncodedImages& images_;
    const Warn sink_ = [this](const std::string& message) { warn(message); };  // warn() for the gltf_* parts
    Scene scene_;
    std::vector<std::optional<std::vector<int>>> meshCache_;  // glTF mesh -> Scene meshes (one per kept primitive)
    std::vector<char> onPath_;                                 // nodes on the current root-to-node path (cycles)
    PrimitiveTally tally_;
    std::size_t visits_ = 0, suppressedWarnings_ = 0, degenerateInstances_ = 0;
    bool cycleWarned_ = false, depthWarned_ = false, visitsWarned_ = false, skinWarned_ = false;
};

const std::vector<int>& Loader::meshPrimitives(int meshIndex) {
    std::optional<std::vector<int>>& cached = meshCache_[std::size_t(meshIndex)];
    if (cached) return *cached;
    cached.emplace();
    const tg::Mesh& gm = model_.meshes[std::size_t(meshIndex)];
    if (gm.primitives.empty()) warn(meshLabel(model_, meshIndex) + " has no (valid) primitives");
    for (std::size_t i = 0; i < gm.primitives.size(); ++i) {
        if (std::optional<Mesh> mesh = convertPrimitive(model_, meshIndex, int(i), sink_, tally_)) {
            cached->push_back(int(scene_.meshes.size()));
            scene_.meshes.push_back(std::move(*mesh));
        }
    }
    return *cached;
}

glm::dmat4 Loader::localMatrix(int index) {
    const tg::Node& node = model_.nodes[std::size_t(index)];
    const std::string where = "node " + str(index);
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, like glm
    if (!node.matrix.empty()) warn(where + ": matrix with " + str(node.matrix.size()) + " values ignored");
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) m = glm::translate(m, glm::make_vec3(node.translation.data()));
    if (node.rotation.size() == 4) {
        const auto& r = node.rotation;  // glTF order x, y, z, w
        glm::dquat q(r[3], r[0], r[1], r[2]);
        const double len = glm::length(q);
        if (len > 1e-12 && std::isfinite(len))
            m *= glm::mat4_cast(q / len);
        else
            warn(where + ": degenerate rotation quaternion ignored");
    }
    if (node.scale.size() == 3) m = glm::scale(m, glm::make_vec3(node.scale.data()));
    return m;
}

void Loader::visit(int index, const glm::dmat4& parent, int depth) {
    if (index < 0 || index >= int(model_.nodes.size())) {
        warn("node " + str(index) + " does not exist; ignored");
        return;
    }
    if (onPath_[std::size_t(index)]) {  // a node that is its own ancestor: cut the loop (RecursiveNodes.gltf)
        if (!cycleWarned_) warn("the node graph has a cycle through node " + str(index) + "; the cycle is cut there");
        cycleWarned_ = true;
        return;
    }
    if (depth > kMaxNodeDepth || ++visits_ > kMaxNodeVisits) {
        bool& warned = depth > kMaxNodeDepth ? depthWarned_ : visitsWarned_;
        if (!warned) warn(depth > kMaxNodeDepth ? "node hierarchy deeper than " + str(kMaxNodeDepth) + "; cut there"
                                                : "more than " + str(kMaxNodeVisits) + " node visits; the rest is cut");
        warned = true;
        return;
    }
    const tg::Node& node = model_.nodes[std::size_t(index)];
    const glm::dmat4 world = parent * localMatrix(index);
    if (!allFinite(world)) {
        warn("node " + str(index) + ": transform is not finite; the node and its children are ignored");
        return;
    }
    if (node.mesh >= int(model_.meshes.size())) warn("node " + str(index) + ": mesh " + str(node.mesh) + " does not exist");
    if (node.mesh >= 0 && node.mesh < int(model_.meshes.size())) {
        if (node.skin >= 0 && !skinWarned_) {
            skinWarned_ = true;
            warn("skinning is ignored: skinned meshes are drawn in their bind pose");
        }
        // A singular transform (scale 0) has no normal matrix: skip it. Negative determinants (mirrors) are kept.
        const double det = glm::determinant(glm::dmat3(world));
        for (int mesh : meshPrimitives(node.mesh)) {
            if (!(std::abs(det) > 1e-30)) {
                ++degenerateInstances_;
                continue;
            }
            scene_.instances.push_back(Instance{mesh, glm::mat4(world)});
        }
    }
    if (std::optional<SceneLight> light = importLight(model_, index, world, sink_)) scene_.lights.push_back(*light);
    onPath_[std::size_t(index)] = 1;
    for (int child : node.children) visit(child, world, depth + 1);
    onPath_[std::size_t(index)] = 0;
}

// The default scene, else scene 0, else every node nobody lists as a child.
std::vector<int> Loader::rootNodes() {
    const int count = int(model_.scenes.size());
    if (model_.defaultScene >= count) warn("default scene " + str(model_.defaultScene) + " does not exist");
    if (count > 0) {
        const int chosen = model_.defaultScene >= 0 && model_.defaultScene < count ? model_.defaultScene : 0;
        const std::vector<int>& nodes = model_.scenes[std::size_t(chosen)].nodes;
        if (nodes.empty()) warn("scene " + str(chosen) + " lists no nodes");
        return nodes;
    }
    std::vector<char> isChild(model_.nodes.size(), 0);
    for (const tg::Node& n : model_.nodes)
        for (int c : n.children)
            if (c >= 0 && c < int(isChild.size())) isChild[std::size_t(c)] = 1;
    std::vector<int> roots;
    for (std::size_t i = 0; i < isChild.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    if (!roots.empty()) warn("the file has no scenes; all " + str(roots.size()) + " root nodes are loaded");
    return roots;
}

std::optional<Scene> Loader::run(std::string& error) {
    if (!checkRequiredExtensions(model_, sink_, error)) return std::nullopt;
    importMaterials(model_, images_, scene_, sink_);
    for (int root : rootNodes()) visit(root, glm::dmat4(1.0), 0);

    if (tally_.zeroAreaTriangles > 0) warn(str(tally_.zeroAreaTriangles) + " zero-area triangles kept (they cast no shadow)");
    if (degenerateInstances_ > 0)
        warn(str(degenerateInstances_) + " mesh instances with a singular (zero-scale) transform skipped");
    if (scene_.instances.empty()) {
        error = "no triangle geometry";
        std::string why;
        for (std::size_t i = 0; i < scene_.warnings.size() && i < 3; ++i) why += (i ? "; " : "") + scene_.warnings[i];
        if (!why.empty()) error += " (" + why + ")";
        return std::nullopt;
    }
    if (suppressedWarnings_ > 0) scene_.warnings.push_back("... and " + str(suppressedWarnings_) + " more warnings");
    scene_.computeBounds();
    if (scene_.bounds.empty) {
        error = "no finite geometry after applying the node transforms";
        return std::nullopt;
    }
    return std::move(scene_);
}

SceneLoadResult failure(const std::string& path, const std::string& what) {
    SceneLoadResult r;
    r.error = path + ": " + what;
    return r;
}

SceneLoadResult loadImpl(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) return failure(path, "file not found");
    if (!fs::is_regular_file(path, ec)) return failure(path, "not a regular file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) return failure(path, "cannot be read (" + ec.message() + ")");
    if (size == 0) return failure(path, "the file is empty");
    if (size >= std::numeric_limits<unsigned int>::max()) return failure(path, "larger than 4 GiB, which glTF cannot be");

    char magic[4] = {};
    std::ifstream(path, std::ios::binary).read(magic, 4);
    const bool binary = std::memcmp(magic, "glTF", 4) == 0;  // GLB by content, whatever the extension says

    tg::Model model;
    tg::TinyGLTF gltf;
    EncodedImages images{&model, {}};
    gltf.SetImageLoader(&keepEncodedImage, &images);
    std::string err, warn;
    const bool ok = binary ? gltf.LoadBinaryFromFile(&model, &err, &warn, path)
                           : gltf.LoadASCIIFromFile(&model, &err, &warn, path);
    if (!ok) {
        if (const std::string ext = unsupportedRequiredExtension(path, binary); !ext.empty())
            return failure(path, compressedGeometryError(ext));
        std::string why = joinLines(err);
        if (why.empty()) why = joinLines(warn);
        if (why.find("File not found") != std::string::npos)
            return failure(path, "a file it refers to is missing (" + why + ")");
        return failure(path, std::string("cannot be loaded as ") + (binary ? "GLB" : "glTF") +
                                 (why.empty() ? "" : " (" + why + ")"));
    }

    Loader loader(model, images);
    for (const std::string& line : splitLines(warn)) loader.warn("tinygltf: " + line);
    std::string error;
    std::optional<Scene> scene = loader.run(error);
    if (!scene) return failure(path, error);
    std::string name = fs::path(path).stem().string();
    if (name.size() > 5 && name.ends_with(".gltf")) name.resize(name.size() - 5);  // X.gltf.json -> X
    scene->name = name;
    return SceneLoadResult{std::move(scene), {}};
}

}  // namespace

SceneLoadResult loadGltfScene(const std::string& path) {
    try {
        return loadImpl(path);
    } catch (const std::bad_alloc&) {
        return failure(path, "out of memory while loading");
    } catch (const std::exception& e) {
        return failure(path, std::string("failed to load: ") + e.what());
    }
}

}  // namespace shadowlab
