#include "scene/scene_fingerprint.h"

#include "scene/hash_combine.h"

#include <functional>

namespace shadowlab {

namespace {

// The material values a depth pass reads (alpha test, culling); the same in both geometry keys.
void hashMaterials(std::size_t& seed, const Scene& scene) {
    hashCombine(seed, scene.materials.size());
    for (const Material& material : scene.materials) {
        hashCombine(seed, std::size_t(material.alphaMode));
        hashBytes(seed, material.alphaCutoff);
        hashBytes(seed, material.baseColorFactor.a);
        hashBytes(seed, material.doubleSided);
        hashBytes(seed, material.uvTransform);
        hashCombine(seed, std::size_t(material.baseColorImage + 1));
    }
}

void hashInstanceMeshes(std::size_t& seed, const Scene& scene) {
    hashCombine(seed, scene.instances.size());
    for (const Instance& instance : scene.instances) hashCombine(seed, std::size_t(instance.mesh));
}

}  // namespace

std::size_t layoutFingerprint(const Scene& scene) {
    std::size_t seed = std::hash<const void*>{}(&scene);
    hashCombine(seed, scene.meshes.size());
    for (const Mesh& mesh : scene.meshes) {
        hashCombine(seed, std::hash<const void*>{}(mesh.positions.data()));
        hashCombine(seed, mesh.positions.size());
        hashCombine(seed, std::hash<const void*>{}(mesh.indices.data()));
        hashCombine(seed, mesh.indices.size());
        hashCombine(seed, std::size_t(mesh.material + 1));
    }
    hashCombine(seed, scene.images.size());
    for (const Image& image : scene.images) hashCombine(seed, std::hash<const void*>{}(image.rgba.data()));
    hashInstanceMeshes(seed, scene);
    hashMaterials(seed, scene);
    return seed;
}

std::size_t geometryFingerprint(const Scene& scene) {
    std::size_t seed = scene.meshes.size();
    for (const Mesh& mesh : scene.meshes) {
        hashContents(seed, mesh.positions);
        hashContents(seed, mesh.normals);
        hashContents(seed, mesh.uvs);
        hashContents(seed, mesh.indices);
        hashCombine(seed, std::size_t(mesh.material + 1));
    }
    hashInstanceMeshes(seed, scene);
    hashMaterials(seed, scene);
    // Images by size only (hashing their bytes would cost more than uploading them): a scene with these very meshes
    // and other pictures of the same sizes is not told apart; an edit in place calls Renderer::sceneChanged.
    hashCombine(seed, scene.images.size());
    for (const Image& image : scene.images) {
        hashCombine(seed, std::size_t(image.width));
        hashCombine(seed, std::size_t(image.height));
    }
    return seed;
}

std::size_t transformsFingerprint(const Scene& scene) {
    std::size_t seed = scene.instances.size();
    for (const Instance& instance : scene.instances) hashBytes(seed, instance.transform);
    return seed;
}

std::size_t sceneFingerprint(const Scene& scene) {
    std::size_t seed = layoutFingerprint(scene);
    hashCombine(seed, transformsFingerprint(scene));
    return seed;
}

}  // namespace shadowlab
