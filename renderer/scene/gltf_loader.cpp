#include "scene/gltf_loader.h"

// The top-level flow: read the file with tinygltf, check its required extensions, import materials, walk the node
// graph from the scene's roots (cycles, depth and blow-up cut), record each visited node (Scene::nodes) and instance
// its mesh primitives and place its camera under its world transform. The parts live in gltf_accessors, gltf_geometry, gltf_primitives, gltf_images, gltf_materials,
// gltf_lights and gltf_extensions.
#include "scene/gltf_animation.h"
#include "scene/gltf_camera_precheck.h"
#include "scene/gltf_cameras.h"
#include "scene/gltf_common.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_geometry.h"
#include "scene/gltf_images.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_precheck.h"
#include "scene/gltf_primitives.h"
#include "scene/scene_animation.h"
#include "settings/regular_file.h"

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
constexpr std::size_t kMaxNodeVisits = 1'000'000;   // a node shared by many parents can explode combinatorially
constexpr std::size_t kMaxWarnings = 100;
constexpr std::size_t kMaxRecordedNodes = 100'000;         // Scene::nodes: the outliner's and presets' node list
constexpr std::size_t kMaxNodePathBytes = std::size_t(64) << 20;  // their paths together (deep, long-named chains)
constexpr double kMaxSceneExtent = 1e18;  // its square, 1e36, is still a float; light-space math squares lengths           // keep the list readable on badly broken files

class Loader {
public:
    Loader(const tg::Model& model, const EncodedImages& images, DecodeBudget& budget)
        : model_(model), images_(images) {
        meshCache_.resize(model.meshes.size());
        onPath_.assign(model.nodes.size(), 0);
        tally_.budget = &budget;
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
    void visit(int index, const glm::dmat4& parent, int depth, int parentNode, bool animatedPath);
    NodeTransform localTransform(int index);

    const tg::Model& model_;
    const EncodedImages& images_;
    const Warn sink_ = [this](const std::string& message) { warn(message); };  // warn() for the gltf_* parts
    Scene scene_;
    std::vector<std::optional<std::vector<int>>> meshCache_;  // glTF mesh -> Scene meshes (one per kept primitive)
    std::vector<char> onPath_;                                 // nodes on the current root-to-node path (cycles)
    PrimitiveTally tally_;
    std::vector<char> animated_;  // glTF nodes some played channel drives
    std::size_t skinnedNodes_ = 0;
    std::size_t visits_ = 0, suppressedWarnings_ = 0, degenerateInstances_ = 0;
    bool cycleWarned_ = false, depthWarned_ = false, visitsWarned_ = false;
    bool instanceCapHit_ = false;
    bool nodesCut_ = false;          // past kMaxRecordedNodes or kMaxNodePathBytes: no more nodes recorded
    std::size_t nodePathBytes_ = 0;
    int capNode_ = -1;  // the node whose instances passed kMaxInstances
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

NodeTransform Loader::localTransform(int index) {
    const tg::Node& node = model_.nodes[std::size_t(index)];
    const std::string where = "node " + str(index);
    NodeTransform t;
    if (node.matrix.size() == 16) {  // column-major, like glm
        t.hasMatrix = true;
        t.matrix = glm::make_mat4(node.matrix.data());
        return t;
    }
    if (!node.matrix.empty()) warn(where + ": matrix with " + str(node.matrix.size()) + " values ignored");
    if (node.translation.size() == 3) t.translation = glm::make_vec3(node.translation.data());
    if (node.rotation.size() == 4) {
        const auto& r = node.rotation;  // glTF order x, y, z, w
        glm::dquat q(r[3], r[0], r[1], r[2]);
        const double len = glm::length(q);
        if (len > 1e-12 && std::isfinite(len))
            t.rotation = q / len;
        else
            warn(where + ": degenerate rotation quaternion ignored");
    }
    if (node.scale.size() == 3) t.scale = glm::make_vec3(node.scale.data());
    return t;
}

void Loader::visit(int index, const glm::dmat4& parent, int depth, int parentNode, bool animatedPath) {
    if (index < 0 || index >= int(model_.nodes.size())) {
        warn("node " + str(index) + " does not exist; ignored");
        return;
    }
    if (instanceCapHit_ || tally_.budget->exceeded) return;  // refused: stop walking at once
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
    const NodeTransform local = localTransform(index);
    const glm::dmat4 world = parent * localMatrix(local);
    animatedPath = animatedPath || animated_[std::size_t(index)];
    if (!fitsFloat(world)) {
        warn("node " + str(index) + ": transform is not finite in float; the node and its children are ignored");
        return;
    }
    // The node as presets name it (its path) and the outliner lists it; its instances point back at it.
    // A file whose node graph multiplies (a node listed by many parents) is not recorded past the limits: its
    // remaining instances belong to no node (they always cast).
    int sceneNode = -1;
    if (!nodesCut_) {
        SceneNode recorded;
        recorded.name = node.name;
        const std::string segment = nodePathSegment(node.name, index);
        recorded.path = parentNode < 0 ? segment : scene_.nodes[std::size_t(parentNode)].path + "/" + segment;
        recorded.parent = parentNode;
        recorded.gltfIndex = index;
        recorded.local = local;
        nodePathBytes_ += recorded.path.size();
        if (scene_.nodes.size() >= kMaxRecordedNodes || nodePathBytes_ > kMaxNodePathBytes) {
            nodesCut_ = true;
            warn("more than " + str(kMaxRecordedNodes) + " nodes or " + str(kMaxNodePathBytes >> 20) +
                 " MiB of node paths: later nodes are not listed (their meshes always cast shadows)");
        } else {
            sceneNode = int(scene_.nodes.size());
            if (parentNode >= 0) scene_.nodes[std::size_t(parentNode)].children.push_back(sceneNode);
            scene_.nodes.push_back(std::move(recorded));
        }
    }
    if (node.mesh >= int(model_.meshes.size())) warn("node " + str(index) + ": mesh " + str(node.mesh) + " does not exist");
    if (node.mesh >= 0 && node.mesh < int(model_.meshes.size())) {
        if (node.skin >= 0) ++skinnedNodes_;
        // A singular transform (scale 0) has no normal matrix: skip it, unless an animation may scale it up (the
        // GPU scene keeps a zero-scale instance's normals finite). Negative determinants (mirrors) are kept.
        const double det = glm::determinant(glm::dmat3(world));
        for (int mesh : meshPrimitives(node.mesh)) {
            if (!(std::abs(det) > 1e-30) && !animatedPath) {
                ++degenerateInstances_;
                continue;
            }
            if (scene_.instances.size() >= kMaxInstances) {
                instanceCapHit_ = true;
                capNode_ = index;
                return;
            }
            scene_.instances.push_back(Instance{mesh, glm::mat4(world), sceneNode});
        }
    }
    // Lights and cameras keep their node: a pose moves them with it (scene_animation.h).
    if (std::optional<SceneLight> light = importLight(model_, index, world, sink_)) {
        light->node = sceneNode;
        scene_.lights.push_back(*light);
    }
    if (std::optional<SceneCamera> camera = importCamera(model_, index, world, sink_)) {
        camera->node = sceneNode;
        scene_.cameras.push_back(*camera);
    }
    onPath_[std::size_t(index)] = 1;
    for (int child : node.children) visit(child, world, depth + 1, sceneNode, animatedPath);
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
    const std::vector<int> baseColorSources = importMaterials(model_, scene_, sink_);
    const std::vector<int> roots = rootNodes();
    if (roots.empty() && !model_.nodes.empty() && model_.scenes.empty()) {
        error = "no scene root: the file has no scenes and each of its " + str(model_.nodes.size()) +
                " nodes is some node's child (the node graph is a cycle)";
        return std::nullopt;
    }
    scene_.animations = importAnimations(model_, *tally_.budget, sink_);
    animated_ = animatedNodes(model_, scene_.animations);
    for (int root : roots) visit(root, glm::dmat4(1.0), 0, -1, false);
    if (skinnedNodes_ > 0)
        warn(str(skinnedNodes_) + " skinned mesh node" + (skinnedNodes_ == 1 ? " is" : "s are") +
             " not played: skins are drawn in their bind pose (their joints' animations move nothing)");
    if (instanceCapHit_) {
        error = "more than " + str(kMaxInstances) + " mesh instances (the limit), reached at node " + str(capNode_) +
                ": nodes listed as children many times over multiply into more copies than can be drawn";
        return std::nullopt;
    }
    if (tally_.budget->exceeded) {
        error = "the scene decodes to more than " + str(kMaxDecodedBytes >> 20) + " MiB (the limit for a scene): " +
                str(tally_.budget->used >> 20) + " MiB of buffers, images and vertex data were read before a " +
                "primitive that needs more";
        return std::nullopt;
    }
    // After the walk: only the images of drawn materials are decoded, and they count against the same budget.
    if (error = importMaterialImages(model_, images_, baseColorSources, scene_, *tally_.budget, sink_); !error.empty())
        return std::nullopt;

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
    extendBoundsOverAnimations(scene_);
    if (scene_.bounds.empty) {
        error = "no finite geometry after applying the node transforms";
        return std::nullopt;
    }
    // The light's volume is built from the bounds in float: their extent must square without overflow.
    const glm::dvec3 lo(scene_.bounds.min), hi(scene_.bounds.max);
    const double extent = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y),
                                    std::abs(hi.z), glm::length(hi - lo)});
    if (!(extent <= kMaxSceneExtent)) {
        error = "the scene's bounds overflow a float: they reach " + str(extent) + " world units, beyond the " +
                str(kMaxSceneExtent) + " whose squares a float can hold (the light's matrices would not be finite)";
        return std::nullopt;
    }
    return std::move(scene_);
}

SceneLoadResult failure(const std::string& path, const std::string& what) {
    SceneLoadResult r;
    r.error = path + ": " + what;
    return r;
}

struct FileAccess {
    DecodeBudget* budget;
};

bool fileExists(const std::string& path, void*) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);  // anything that exists: reading it then says what it is
}

std::string expandNothing(const std::string& path, void*) { return path; }

bool readBudgetedFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    DecodeBudget& budget = *static_cast<FileAccess*>(user)->budget;
    std::string why = readRegularFile(path, kMaxDecodedBytes - budget.used, *out);
    if (why.empty() && budget.take(out->size())) return true;
    if (why.empty()) why = path + ": passes the scene's " + str(kMaxDecodedBytes >> 20) + " MiB decode limit";
    if (err) *err += why.substr(std::min(why.size(), path.size() + 2));  // tinygltf prefixes the path itself
    out->clear();
    return false;
}

bool writeNothing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not allowed while loading";
    return false;
}

SceneLoadResult loadBytes(const std::vector<unsigned char>& bytes, const std::string& label, const std::string& baseDir) {
    if (bytes.empty()) return failure(label, "the file is empty");
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;  // GLB by content
    const std::string_view json =
        binary ? glbJsonChunk(bytes) : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (std::string problem = precheckGltfJson(json); !problem.empty()) return failure(label, problem);
    // A camera tinygltf cannot parse would sink the whole file: it is stood in for and refused alone.
    std::vector<unsigned char> standIn;
    if (std::optional<std::string> fixed = standInBrokenCameras(json))
        standIn = binary ? glbWithJson(bytes, json, *fixed) : std::vector<unsigned char>(fixed->begin(), fixed->end());
    const std::vector<unsigned char>& input = standIn.empty() ? bytes : standIn;

    DecodeBudget budget;
    budget.take(bytes.size());
    FileAccess access{&budget};
    tg::Model model;
    tg::TinyGLTF gltf;
    gltf.SetFsCallbacks(tg::FsCallbacks{&fileExists, &expandNothing, &readBudgetedFile, &writeNothing, &access});
    EncodedImages images{&model, &budget, {}, {}};
    gltf.SetImageLoader(&keepEncodedImage, &images);
    std::string err, warn;
    const auto size = static_cast<unsigned int>(input.size());
    const bool ok = binary ? gltf.LoadBinaryFromMemory(&model, &err, &warn, input.data(), size, baseDir)
                           : gltf.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(input.data()),
                                                      size, baseDir);
    if (!ok) {
        if (const std::string ext = unsupportedRequiredExtension(json); !ext.empty())
            return failure(label, compressedGeometryError(ext));
        std::string why = joinLines(err);
        if (why.empty()) why = joinLines(warn);
        if (why.find("File not found") != std::string::npos)
            return failure(label, "a file it refers to is missing (" + why + ")");
        return failure(label, std::string("cannot be loaded as ") + (binary ? "GLB" : "glTF") +
                                  (why.empty() ? "" : " (" + why + ")"));
    }

    Loader loader(model, images, budget);
    for (const std::string& line : splitLines(warn)) loader.warn("tinygltf: " + line);
    std::string error;
    std::optional<Scene> scene = loader.run(error);
    if (!scene) return failure(label, error);
    return SceneLoadResult{std::move(scene), {}};
}

SceneLoadResult loadImpl(const std::string& path) {
    namespace fs = std::filesystem;
    std::vector<unsigned char> bytes;
    // Only a regular file: a FIFO would block, a folder or a device is no scene. glTF cannot pass 4 GiB.
    if (std::string why = readRegularFile(path, std::numeric_limits<unsigned int>::max() - 1u, bytes); !why.empty()) {
        if (why.ends_with(": no such file")) return failure(path, "file not found");
        return SceneLoadResult{std::nullopt, why};
    }
    const std::string baseDir = fs::path(path).parent_path().string();
    SceneLoadResult r = loadBytes(bytes, path, baseDir.empty() ? "." : baseDir);
    if (!r.scene) return r;
    std::string name = fs::path(path).stem().string();
    if (name.size() > 5 && name.ends_with(".gltf")) name.resize(name.size() - 5);  // X.gltf.json -> X
    r.scene->name = name;
    return r;
}

}  // namespace

SceneLoadResult loadGltfSceneFromMemory(const std::vector<unsigned char>& bytes, const std::string& label,
                                        const std::string& baseDir) {
    try {
        SceneLoadResult r = loadBytes(bytes, label, baseDir);
        if (r.scene) r.scene->name = label;
        return r;
    } catch (const std::bad_alloc&) {
        return failure(label, "out of memory while loading");
    } catch (const std::exception& e) {
        return failure(label, std::string("failed to load: ") + e.what());
    }
}

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
