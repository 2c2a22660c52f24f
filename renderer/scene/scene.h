#pragma once
// The scene model the renderer draws: triangle meshes, materials (alpha only matters for shadows), instances with
// world transforms, optional punctual lights. No GL here; the renderer uploads it (see gpu_scene.h).
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <glm/mat3x3.hpp>
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double3.hpp>

#include "scene/node_animation.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

enum class AlphaMode { Opaque, Mask, Blend };

// RGBA8 image; only the alpha channel is used (alpha-tested shadow casters).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width*height*4 bytes, row 0 = first row of the file (glTF uv (0,0) = top-left)
    bool valid() const { return width > 0 && height > 0 && rgba.size() == std::size_t(width) * height * 4; }
};

struct Material {
    std::string name;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    glm::vec4 baseColorFactor{1.0f};
    int baseColorImage = -1;         // index into Scene::images, -1 = none
    int baseColorTexCoord = 0;       // which UV set (only TEXCOORD_0 is loaded; others fall back to it with a warning)
    glm::mat3 uvTransform{1.0f};     // KHR_texture_transform of the base colour texture, identity if absent
    bool wrapRepeat = true;          // sampler wrap of the base colour texture (repeat vs clamp)
    bool doubleSided = false;
};

// One primitive: an indexed triangle list (non-indexed input gets 0..n-1 indices).
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // same count as positions (computed flat/smooth when the file has none)
    std::vector<glm::vec2> uvs;      // empty or same count as positions
    std::vector<std::uint32_t> indices;
    int material = -1;               // index into Scene::materials, -1 = default opaque
    std::size_t triangleCount() const { return indices.size() / 3; }
};

struct Instance {
    int mesh = 0;
    glm::mat4 transform{1.0f};  // object to world
    int node = -1;              // the SceneNode it was placed by; -1 = none (built-in scenes)
    bool mirrored() const;      // negative determinant: triangle winding is reversed in world space
};

enum class SceneLightType { Directional, Spot, Point };

struct SceneLight {
    std::string name;
    SceneLightType type = SceneLightType::Directional;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // world direction the light travels (glTF: node's -Z)
    float outerConeRad = 0.7853982f;         // spot only
    float range = 0.0f;                      // 0 = infinite
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    int node = -1;  // the SceneNode that places it (an animation moves it with its node); -1 = none
};

// A camera of the file (glTF `cameras`, placed by the node that uses it). The view's aspect ratio is the window's,
// never the file's; a camera's roll is not kept (the view's up stays +y, as the free camera's).
struct SceneCamera {
    std::string name;                    // the camera's name, else its node's, else "camera N"
    int index = 0;                       // in the file's `cameras` list (messages name it)
    glm::dvec3 position{0.0};            // world
    glm::dvec3 forward{0.0, 0.0, -1.0};  // unit, world: the node's -Z
    bool orthographic = false;
    double yfovRad = 0.8;                // perspective: vertical field of view
    double ymag = 1.0;                   // orthographic: half the view's height, world units (xmag follows the aspect)
    double znear = 0.1;
    double zfar = 0.0;                   // 0 = infinite (perspective without zfar)
    int node = -1;                       // the SceneNode that places it (an animation moves it); -1 = none
};

// Where a light or camera a node carries stands and looks under the node's world transform: glTF puts both at the
// node's origin, looking along its -Z. `forward` is unit, nullopt when the transform has no -Z (zero scale) or
// is not finite.
struct NodeFrame {
    glm::dvec3 position{0.0};
    std::optional<glm::dvec3> forward;
};
NodeFrame nodeFrame(const glm::dmat4& world);

// A node of the file's hierarchy as the loader walked it from the scene's roots (a node two parents list appears
// under each). `path` names it in presets: the names from the root down joined by '/', an unnamed node as
// "#<glTF node index>", a '/' or '\' inside a name and a leading '#' escaped with '\' (see nodePathSegment).
struct SceneNode {
    std::string name;
    std::string path;
    int parent = -1;            // index into Scene::nodes, -1 = a root
    std::vector<int> children;  // indices into Scene::nodes, in the file's order
    int gltfIndex = -1;         // the file's node (what animation channels target)
    NodeTransform local;        // its transform in the file (the rest pose animations start from)
};

// One segment of a node path: the name with '/', '\' and a leading '#' escaped, or "#<index>" for an unnamed node.
std::string nodePathSegment(const std::string& name, int gltfIndex);

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    bool empty = true;
    glm::vec3 center() const { return (min + max) * 0.5f; }
    glm::dvec3 centreOrOrigin() const { return empty ? glm::dvec3(0.0) : glm::dvec3(center()); }  // empty: the origin
    float radius() const;  // half the diagonal (bounding sphere around the box)
    void extend(const glm::vec3& p);  // ignores non-finite points
};

struct Scene {
    std::string name;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<Instance> instances;
    std::vector<SceneLight> lights;
    std::vector<SceneCamera> cameras;  // the file's cameras that passed the checks, in the order their nodes were met
    std::vector<SceneNode> nodes;      // the walked hierarchy, parents before children; empty for built-in scenes
    // The file's node animations that passed the checks (scene_animation.h poses the scene at a time); bounds cover
    // every pose they reach, so a light fitted to the bounds holds still while they play.
    std::vector<Animation> animations;
    std::vector<std::string> warnings;  // what was repaired or ignored while loading

    // Unit direction from the scene's centre toward an auto-framed camera: of eight three-quarter views from above,
    // the one that sees the most front-facing surface (a single-sided board is shown from its front). Set by
    // computeBounds().
    glm::vec3 viewDirection = kDefaultViewDirection;
    static constexpr glm::vec3 kDefaultViewDirection{0.4921f, 0.5905f, -0.6397f};

    // Where the scene is meant to be seen from, when framing it whole shows nothing of interest (builtin:city: eye
    // height in a street of a 2 km city). When set, an auto-framed camera stands here (frame/camera.h).
    struct Viewpoint {
        glm::dvec3 position{0.0};
        glm::dvec3 target{0.0, 0.0, -1.0};
    };
    std::optional<Viewpoint> viewpoint;

    // World-space bounds over every instance's finite vertices, and viewDirection (cached by computeBounds()).
    Bounds bounds;
    void computeBounds();

    std::size_t triangleCount() const;  // over all instances
    // Empty when everything the renderer relies on holds (indices in range, matching attribute counts, finite
    // positions, unit normals, valid material/image/mesh references, finite transforms); else the first problem.
    std::string invariantError() const;
    const Material* materialOf(const Mesh& mesh) const;
    bool hasAlphaMaskedCasters() const;
};

}  // namespace shadowlab
