#include "frame/gpu_scene.h"

#include "scene/scene_fingerprint.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace shadowlab {

namespace {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

// The mesh's bounding sphere in render-origin-relative world space, from the box of its finite vertices.
void computeDrawBounds(const Bounds& box, const glm::dmat4& model, GpuDraw& draw) {
    draw.boundsCenter = glm::vec3(0.0f);
    draw.boundsRadius = 0.0f;
    draw.hasFiniteBounds = false;
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

glm::dmat4 toOriginMatrix(const glm::dvec3& origin) {
    return glm::dmat4(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -origin.x, -origin.y, -origin.z, 1.0);
}

}  // namespace

void bindDrawTransformsBlock(GLuint program) {
    const GLuint block = glGetProgramResourceIndex(program, GL_SHADER_STORAGE_BLOCK, "DrawTransforms");
    if (block != GL_INVALID_INDEX) glShaderStorageBlockBinding(program, block, kDrawTransformsBinding);
}

std::string SceneUpload::describe() const {
    if (geometry)
        return "geometry uploaded, " + std::to_string(geometryBytes + transformBytes) + " bytes (vertices, indices, "
               "textures and " + std::to_string(drawsMoved) + " transforms)";
    if (drawsMoved == 0) return "nothing uploaded: the same geometry, no draw moved";
    return "transforms updated, " + std::to_string(transformBytes) + " bytes (" + std::to_string(drawsMoved) +
           (drawsMoved == 1 ? " draw" : " draws") + " moved; no geometry uploaded)";
}

void GpuScene::placeDraw(const Instance& instance, const glm::dmat4& toOrigin, GpuDraw& draw) const {
    const glm::dmat4 model = toOrigin * glm::dmat4(instance.transform);
    draw.model = glm::mat4(model);
    // A zero-scale node has no inverse: keep its (degenerate) linear part so no NaN reaches the GPU.
    const glm::dmat3 linear(model);
    draw.normalMatrix = std::abs(glm::determinant(linear)) > 1e-30 ? glm::mat3(glm::transpose(glm::inverse(linear)))
                                                                    : glm::mat3(linear);
    draw.mirrored = instance.mirrored();
    computeDrawBounds(meshBoxes_[std::size_t(instance.mesh)], model, draw);
}

GpuScene::GpuScene(const Scene& scene, const glm::dvec3& origin) : scene_(&scene), origin_(origin) {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<GLint> meshBaseVertex;
    std::vector<std::size_t> meshFirstIndex;
    for (const Mesh& mesh : scene.meshes) {
        meshBaseVertex.push_back(GLint(vertices.size()));
        meshFirstIndex.push_back(indices.size());
        Bounds box;
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            Vertex v{mesh.positions[i], i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0),
                     i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f)};
            vertices.push_back(v);
            box.extend(mesh.positions[i]);
        }
        meshBoxes_.push_back(box);
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
    }

    vertices_ = gl::createBuffer();
    indices_ = gl::createBuffer();
    glNamedBufferStorage(vertices_.id(), GLsizeiptr(std::max<std::size_t>(vertices.size(), 1) * sizeof(Vertex)),
                         vertices.empty() ? nullptr : vertices.data(), 0);
    glNamedBufferStorage(indices_.id(), GLsizeiptr(std::max<std::size_t>(indices.size(), 1) * sizeof(std::uint32_t)),
                         indices.empty() ? nullptr : indices.data(), 0);
    lastUpload_.geometry = true;
    lastUpload_.geometryBytes = vertices.size() * sizeof(Vertex) + indices.size() * sizeof(std::uint32_t);

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
        lastUpload_.geometryBytes += image.rgba.size() * 4 / 3;
        imageTextures_.push_back(std::move(texture));
    }

    const glm::dmat4 toOrigin = toOriginMatrix(origin);
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
        placeDraw(instance, toOrigin, draw);
        draws_.push_back(draw);
    }

    // The transform buffer (rewritten in place by updateTransforms) and the draw indices 0..N-1.
    std::vector<glm::mat4> models(std::max<std::size_t>(draws_.size(), 1), glm::mat4(1.0f));
    std::vector<std::uint32_t> drawIndices(models.size());
    for (std::size_t d = 0; d < draws_.size(); ++d) models[d] = draws_[d].model;
    std::iota(drawIndices.begin(), drawIndices.end(), 0u);
    transforms_ = gl::createBuffer();
    glNamedBufferStorage(transforms_.id(), GLsizeiptr(models.size() * sizeof(glm::mat4)), models.data(),
                         GL_DYNAMIC_STORAGE_BIT);
    drawIndices_ = gl::createBuffer();
    glNamedBufferStorage(drawIndices_.id(), GLsizeiptr(drawIndices.size() * sizeof(std::uint32_t)),
                         drawIndices.data(), 0);
    lastUpload_.transformBytes = draws_.size() * sizeof(glm::mat4);
    lastUpload_.drawsMoved = int(draws_.size());
    lastUpload_.geometryBytes += drawIndices.size() * sizeof(std::uint32_t);

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
    // Binding 1: one draw index per instance; a draw's baseInstance picks its entry (draws without one read 0).
    glVertexArrayVertexBuffer(vao, 1, drawIndices_.id(), 0, sizeof(std::uint32_t));
    glVertexArrayBindingDivisor(vao, 1, 1);
    glEnableVertexArrayAttrib(vao, kDrawIndexAttribute);
    glVertexArrayAttribIFormat(vao, kDrawIndexAttribute, 1, GL_UNSIGNED_INT, 0);
    glVertexArrayAttribBinding(vao, kDrawIndexAttribute, 1);

    layout_ = layoutFingerprint(scene);
    geometry_ = shadowlab::geometryFingerprint(scene);
}

bool GpuScene::sameGeometry(const Scene& scene) const {
    return layoutFingerprint(scene) == layout_ || shadowlab::geometryFingerprint(scene) == geometry_;
}

const SceneUpload& GpuScene::updateTransforms(const Scene& scene, const glm::dvec3& origin) {
    scene_ = &scene;
    origin_ = origin;
    layout_ = layoutFingerprint(scene);
    lastUpload_ = SceneUpload{};
    const glm::dmat4 toOrigin = toOriginMatrix(origin);
    // Runs of consecutive moved draws go up as one write each.
    std::size_t runStart = 0, runEnd = 0;
    auto flush = [&] {
        if (runEnd == runStart) return;
        std::vector<glm::mat4> run;
        for (std::size_t d = runStart; d < runEnd; ++d) run.push_back(draws_[d].model);
        const std::size_t bytes = run.size() * sizeof(glm::mat4);
        glNamedBufferSubData(transforms_.id(), GLintptr(runStart * sizeof(glm::mat4)), GLsizeiptr(bytes), run.data());
        lastUpload_.transformBytes += bytes;
    };
    for (std::size_t d = 0; d < draws_.size(); ++d) {
        GpuDraw& draw = draws_[d];
        const glm::mat4 before = draw.model;
        placeDraw(scene.instances[draw.instance], toOrigin, draw);
        if (std::memcmp(&before, &draw.model, sizeof before) == 0) continue;
        ++lastUpload_.drawsMoved;
        lastUpload_.moved.push_back(d);
        if (runEnd != d) {
            flush();
            runStart = d;
        }
        runEnd = d + 1;
    }
    flush();
    return lastUpload_;
}

void GpuScene::setCasting(const std::vector<char>& castingInstances) {
    for (GpuDraw& draw : draws_) draw.casts = draw.instance >= castingInstances.size() || castingInstances[draw.instance];
}

void GpuScene::bind() const {
    glBindVertexArray(vao_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDrawTransformsBinding, transforms_.id());
}

GLuint GpuScene::materialTexture(int material) const {
    if (material < 0 || material >= int(scene_->materials.size())) return 0;
    const int image = scene_->materials[std::size_t(material)].baseColorImage;
    if (image < 0 || image >= int(imageTextures_.size())) return 0;
    return imageTextures_[std::size_t(image)].id();
}

}  // namespace shadowlab
