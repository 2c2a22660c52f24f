#include "accuracy/gbuffer_pass.h"

#include "frame/face_culling.h"
#include "gl/program.h"
#include "reference/parallel_rows.h"
#include "reference/pixel_vector.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <chrono>
#include <cmath>

namespace shadowlab {

namespace {

constexpr GLuint kBaseColorUnit = 1;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

GBufferPass::GBufferPass() { program(false, false); }

const GBufferPass::Program& GBufferPass::program(bool alphaMask, bool alphaTexture) {
    const auto key = std::make_pair(alphaMask, alphaTexture);
    if (auto found = programs_.find(key); found != programs_.end()) return found->second;
    std::vector<std::string> defines;
    if (alphaMask) defines.push_back("ALPHA_MASK");
    if (alphaTexture) defines.push_back("BASE_COLOR_TEXTURE");
    Program p;
    p.program = gl::buildProgram({{GL_VERTEX_SHADER, "main.vert.glsl"}, {GL_FRAGMENT_SHADER, "gbuffer.frag.glsl"}},
                                 defines);
    const GLuint id = p.program.id();
    p.viewProjection = glGetUniformLocation(id, "uViewProjection");
    p.model = glGetUniformLocation(id, "uModel");
    p.normalMatrix = glGetUniformLocation(id, "uNormalMatrix");
    p.uvTransform = glGetUniformLocation(id, "uUvTransform");
    p.drawId = glGetUniformLocation(id, "uDrawId");
    p.alphaFactor = glGetUniformLocation(id, "uAlphaFactor");
    p.alphaCutoff = glGetUniformLocation(id, "uAlphaCutoff");
    p.baseColorTexture = glGetUniformLocation(id, "uBaseColorTexture");
    return programs_.emplace(key, std::move(p)).first->second;
}

std::string GBufferPass::ensureTarget(int width, int height) {
    if (width == width_ && height == height_ && framebuffer_) return {};
    gl::Texture ids = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(ids.id(), 1, GL_RG32UI, width, height);
    gl::Renderbuffer depth = gl::createRenderbuffer();
    glNamedRenderbufferStorage(depth.id(), GL_DEPTH_COMPONENT32F, width, height);  // as the main pass's target
    gl::Framebuffer framebuffer = gl::createFramebuffer();
    glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, ids.id(), 0);
    glNamedFramebufferRenderbuffer(framebuffer.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
    if (glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return "accuracy G-buffer framebuffer incomplete at " + std::to_string(width) + "x" + std::to_string(height);
    ids_ = std::move(ids);
    depth_ = std::move(depth);
    framebuffer_ = std::move(framebuffer);
    width_ = width;
    height_ = height;
    return {};
}

std::string GBufferPass::render(const GpuScene& gpuScene, const glm::dmat4& viewProjection, int width, int height,
                                const glm::dvec3& cameraPosition, SurfaceSamples& out) {
    using Clock = std::chrono::steady_clock;
    auto msSince = [](Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); };
    auto t = Clock::now();
    if (std::string error = ensureTarget(width, height); !error.empty()) return error;
    const Scene& scene = gpuScene.scene();

    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, width, height);
    const GLuint zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferuiv(framebuffer_.id(), GL_COLOR, 0, zero);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    const float one = 1.0f;
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &one);

    gpuScene.bind();
    const glm::mat4 vp(viewProjection);
    const std::vector<GpuDraw>& draws = gpuScene.draws();
    for (std::size_t d = 0; d < draws.size(); ++d) {
        const GpuDraw& draw = draws[d];
        const Material* material = draw.material >= 0 ? &scene.materials[std::size_t(draw.material)] : nullptr;
        const bool alphaMask = material && material->alphaMode == AlphaMode::Mask;
        const GLuint alphaTexture = alphaMask ? gpuScene.materialTexture(draw.material) : 0;
        const Program& p = program(alphaMask, alphaTexture != 0);
        glUseProgram(p.program.id());
        glUniformMatrix4fv(p.viewProjection, 1, GL_FALSE, glm::value_ptr(vp));
        glUniformMatrix4fv(p.model, 1, GL_FALSE, glm::value_ptr(draw.model));
        glUniformMatrix3fv(p.normalMatrix, 1, GL_FALSE, glm::value_ptr(draw.normalMatrix));
        const glm::mat3 uvTransform = material ? material->uvTransform : glm::mat3(1.0f);
        glUniformMatrix3fv(p.uvTransform, 1, GL_FALSE, glm::value_ptr(uvTransform));
        glUniform1ui(p.drawId, GLuint(d));
        if (alphaMask) {
            glUniform1f(p.alphaFactor, material->baseColorFactor.a);
            glUniform1f(p.alphaCutoff, material->alphaCutoff);
            if (alphaTexture) {
                glUniform1i(p.baseColorTexture, GLint(kBaseColorUnit));
                glBindTextureUnit(kBaseColorUnit, alphaTexture);
            }
        }
        applyViewFaceCulling(material, draw.mirrored);  // the main pass's rule: what it draws is measured
        glDrawElementsBaseVertex(GL_TRIANGLES, draw.indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(draw.firstIndexByte), draw.baseVertex);
    }
    resetFaceCulling();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    timings_.drawMs = msSince(t);
    t = Clock::now();

    // The (draw + 1, triangle) ids are read in place, mapped.
    const std::size_t count = std::size_t(width) * std::size_t(height);
    const bool mapped =
        readBack_.read(ids_.id(), GL_RG_INTEGER, GL_UNSIGNED_INT, count * 2 * sizeof(GLuint), [&](const void* ids) {
            timings_.readBackMs = msSince(t);
            t = Clock::now();
            rebuild(gpuScene, viewProjection, width, height, cameraPosition, static_cast<const GLuint*>(ids), out);
        });
    if (!mapped) return "accuracy G-buffer: its read-back buffer could not be mapped (GPU out of memory?)";
    timings_.rebuildMs = msSince(t);
    return {};
}

void GBufferPass::rebuild(const GpuScene& gpuScene, const glm::dmat4& viewProjection, int width, int height,
                          const glm::dvec3& cameraPosition, const GLuint* ids, SurfaceSamples& out) const {
    const Scene& scene = gpuScene.scene();
    const std::size_t count = std::size_t(width) * std::size_t(height);
    // Draw d of the GpuScene is the d-th instance whose mesh has triangles (GpuScene skips empty meshes).
    std::vector<const Instance*> drawInstance;
    for (const Instance& instance : scene.instances)
        if (!scene.meshes[std::size_t(instance.mesh)].indices.empty()) drawInstance.push_back(&instance);
    const glm::dvec3 origin = gpuScene.origin();
    const glm::dmat4 toOrigin = glm::dmat4(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -origin.x,
                                           -origin.y, -origin.z, 1.0);
    // Each draw's model matrix once (the same product every pixel of it would form).
    std::vector<glm::dmat4> drawModel(drawInstance.size());
    for (std::size_t d = 0; d < drawInstance.size(); ++d)
        drawModel[d] = toOrigin * glm::dmat4(drawInstance[d]->transform);

    out.width = width;
    out.height = height;
    // Uninitialized (PixelVector): the rows below write every entry, on every core.
    out.draw.resize(count);
    out.instance.resize(count);
    out.triangle.resize(count);
    out.point.resize(count);
    out.normal.resize(count);
    out.finite.resize(count);
    const glm::dmat4 inverse = glm::inverse(viewProjection);
    parallelRows(height, [&](int rowTop) {
        const int rowGl = height - 1 - rowTop;
        for (int x = 0; x < width; ++x) {
            const std::size_t src = (std::size_t(rowGl) * std::size_t(width) + std::size_t(x)) * 2;
            const std::size_t i = std::size_t(rowTop) * std::size_t(width) + std::size_t(x);
            // Background until the ids say otherwise.
            out.draw[i] = out.instance[i] = out.triangle[i] = -1;
            out.point[i] = out.normal[i] = glm::dvec3(0.0);
            out.finite[i] = 0;
            if (ids[src] == 0) continue;
            const std::size_t d = ids[src] - 1;
            const std::size_t triangle = ids[src + 1];
            if (d >= drawInstance.size()) continue;
            out.draw[i] = std::int32_t(d);
            const Instance& instance = *drawInstance[d];
            const Mesh& mesh = scene.meshes[std::size_t(instance.mesh)];
            if (triangle >= mesh.triangleCount()) continue;
            out.instance[i] = std::int32_t(&instance - scene.instances.data());
            out.triangle[i] = std::int32_t(triangle);
            const glm::dmat4& model = drawModel[d];
            glm::dvec3 v[3];
            for (int k = 0; k < 3; ++k)
                v[k] = glm::dvec3(model * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[triangle * 3 + std::size_t(k)]]), 1.0));
            // The pixel centre's camera ray, through the near and far planes.
            const double ndcX = (double(x) + 0.5) / width * 2.0 - 1.0;
            const double ndcY = (double(rowGl) + 0.5) / height * 2.0 - 1.0;
            const glm::dvec4 nearH = inverse * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
            const glm::dvec4 farH = inverse * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
            const glm::dvec3 rayOrigin = glm::dvec3(nearH) / nearH.w;
            const glm::dvec3 rayDirection = glm::dvec3(farH) / farH.w - rayOrigin;
            glm::dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
            const double nLength = glm::length(n);
            const double denominator = glm::dot(n, rayDirection);
            if (!(nLength > 0.0) || denominator == 0.0) continue;
            n /= nLength;
            const double t = glm::dot(n * nLength, v[0] - rayOrigin) / denominator;
            const glm::dvec3 p = rayOrigin + t * rayDirection;
            if (glm::dot(n, cameraPosition - p) < 0.0) n = -n;  // the visible side, as the main pass shades it
            out.point[i] = p;
            out.normal[i] = n;
            out.finite[i] = finite(p) && finite(n) ? 1 : 0;
        }
    });
}

}  // namespace shadowlab
