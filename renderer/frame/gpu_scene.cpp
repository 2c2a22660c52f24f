#include "frame/gpu_scene.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

// The mesh's bounding sphere in render-origin-relative world space, from its finite vertices only.
void computeDrawBounds(const Mesh& mesh, const glm::dmat4& model, GpuDraw& draw) {
    Bounds box;
    for (const glm::vec3& p : mesh.positions) box.extend(p);
    if (box.empty) return;
    glm::dvec3 corners[8];
    for (int i = 0; i < 8; ++i) {
        glm::dvec3 c((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z);
        corners[i] = glm::dvec3(model * glm::dvec4(c, 1.0));
    }
    glm::dvec3 lo = corners[0], hi = corners[0];
    for (const glm::dvec3& c : corners) {
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
    }
    const glm::dvec3 center = 0.5 * (lo + hi);
    const double radius = 0.5 * glm::length(hi - lo);
    if (!std::isfinite(radius)) return;
    draw.boundsCenter = glm::vec3(center);
    draw.boundsRadius = float(radius) * 1.0001f + 1e-6f;
    draw.hasFiniteBounds = true;
}

glm::dmat4 toOriginOf(const glm::dvec3& origin) {
    return glm::dmat4(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -origin.x, -origin.y, -origin.z, 1.0);
}

// The draw's model and normal matrices, winding and bounds at its instance's transform.
void place(GpuDraw& draw, const Instance& instance, const Mesh& mesh, const glm::dmat4& toOrigin) {
    const glm::dmat4 model = toOrigin * glm::dmat4(instance.transform);
    draw.model = glm::mat4(model);
    // A zero-scale node has no inverse: keep its (degenerate) linear part so no NaN reaches the GPU.
    const glm::dmat3 linear(model);
    draw.normalMatrix = std::abs(glm::determinant(linear)) > 1e-30 ? glm::mat3(glm::transpose(glm::inverse(linear)))
                                                                    : glm::mat3(linear);
    draw.mirrored = instance.mirrored();
    draw.hasFiniteBounds = false;
    computeDrawBounds(mesh, model, draw);
}

}  // namespace

GpuScene::GpuScene(const Scene& scene, const glm::dvec3& origin) : scene_(&scene), origin_(origin) {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<GLint> meshBaseVertex;
    std::vector<std::size_t> meshFirstIndex;
    for (const Mesh& mesh : scene.meshes) {
        meshBaseVertex.push_back(GLint(vertices.size()));
        meshFirstIndex.push_back(indices.size());
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            Vertex v{mesh.positions[i], i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0),
                     i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f)};
            vertices.push_back(v);
        }
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
    }

    vertices_ = gl::createBuffer();
    indices_ = gl::createBuffer();
    glNamedBufferStorage(vertices_.id(), GLsizeiptr(std::max<std::size_t>(vertices.size(), 1) * sizeof(Vertex)),
                         vertices.empty() ? nullptr : vertices.data(), 0);
    glNamedBufferStorage(indices_.id(), GLsizeiptr(std::max<std::size_t>(indices.size(), 1) * sizeof(std::uint32_t)),
                         indices.empty() ? nullptr : indices.data(), 0);
    uploadedBytes_ = vertices.size() * sizeof(Vertex) + indices.size() * sizeof(std::uint32_t);

    vao_ = gl::createVertexArray();
    const GLuint vao = vao_.id();
    glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, indices_.id());
    const GLuint offsets[3] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, uv)};
    const GLint sizes[3] = {3, 3, 2};
    for (GLuint attribute = 0; attribute < 3; ++attribute) {
        glEnableVertexArrayAttrib(vao, attribute);
        glVertexArrayAttribFormat(vao, attribute, sizes[attribute], GL_FLOAT, GL_FALSE, offsets[attribute]);
        glVertexArrayAttribBinding(vao, attribute, 0);
    }

    for (const Image& image : scene.images) {
        if (!image.valid()) {
            imageTextures_.emplace_back();
            continue;
        }
        gl::Texture texture = gl::createTexture(GL_TEXTURE_2D);
        const int levels = 1 + int(std::floor(std::log2(double(std::max(image.width, image.height)))));
        glTextureStorage2D(texture.id(), levels, GL_RGBA8, image.width, image.height);
        glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                            image.rgba.data());
        glGenerateTextureMipmap(texture.id());
        glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        uploadedBytes_ += image.rgba.size() * 4 / 3;
        imageTextures_.push_back(std::move(texture));
    }

    const glm::dmat4 toOrigin = toOriginOf(origin);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        const Mesh& mesh = scene.meshes[std::size_t(instance.mesh)];
        if (mesh.indices.empty()) continue;
        GpuDraw draw;
        draw.instance = i;
        draw.indexCount = GLsizei(mesh.indices.size());
        draw.firstIndexByte = meshFirstIndex[std::size_t(instance.mesh)] * sizeof(std::uint32_t);
        draw.baseVertex = meshBaseVertex[std::size_t(instance.mesh)];
        draw.material = mesh.material;
        place(draw, instance, mesh, toOrigin);
        draws_.push_back(draw);
        transforms_.push_back(instance.transform);
    }
}

std::vector<std::size_t> GpuScene::updateTransforms(const Scene& scene) {
    scene_ = &scene;
    std::vector<std::size_t> moved;
    const glm::dmat4 toOrigin = toOriginOf(origin_);
    for (std::size_t d = 0; d < draws_.size(); ++d) {
        const Instance& instance = scene.instances[draws_[d].instance];
        if (instance.transform == transforms_[d]) continue;
        transforms_[d] = instance.transform;
        place(draws_[d], instance, scene.meshes[std::size_t(instance.mesh)], toOrigin);
        moved.push_back(d);
    }
    return moved;
}

void GpuScene::setCasting(const std::vector<char>& castingInstances) {
    for (GpuDraw& draw : draws_) draw.casts = draw.instance >= castingInstances.size() || castingInstances[draw.instance];
}

void GpuScene::bind() const { glBindVertexArray(vao_.id()); }

GLuint GpuScene::materialTexture(int material) const {
    if (material < 0 || material >= int(scene_->materials.size())) return 0;
    const int image = scene_->materials[std::size_t(material)].baseColorImage;
    if (image < 0 || image >= int(imageTextures_.size())) return 0;
    return imageTextures_[std::size_t(image)].id();
}

}  // namespace shadowlab
