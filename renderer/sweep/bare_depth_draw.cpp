#include "sweep/bare_depth_draw.h"

#include "frame/gpu_scene.h"
#include "frame/timed_frames.h"
#include "gl/program.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <vector>

namespace shadowlab {

BareDepthDraw::BareDepthDraw(const Scene& scene, const glm::dvec3& origin, TimingSource source,
                             const std::vector<char>* instances)
    // The shadow pass's own depth-only vertex stage (with one identity model matrix in its transform buffer): the
    // same vertex work per triangle, so the difference is what the pass adds around the raster.
    : program_(gl::buildProgram({{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"}}, {})), timer_(source) {
    lightViewProjection_ = glGetUniformLocation(program_.id(), "uLightViewProjection");
    bindDrawTransformsBlock(program_.id());
    std::vector<glm::vec3> triangles;
    triangles.reserve(scene.triangleCount() * 3);
    for (std::size_t n = 0; n < scene.instances.size(); ++n) {
        if (instances && (n >= instances->size() || !(*instances)[n])) continue;
        const Instance& instance = scene.instances[n];
        const Mesh& mesh = scene.meshes[std::size_t(instance.mesh)];
        glm::dmat4 model = glm::dmat4(instance.transform);
        model[3] -= glm::dvec4(origin, 0.0);  // relative to the render origin, in double precision
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            glm::vec3 corner[3];
            bool finite = true;
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::dvec3 p = glm::dvec3(model * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[i + k]]), 1.0));
                corner[k] = glm::vec3(p);
                finite = finite && std::isfinite(corner[k].x) && std::isfinite(corner[k].y) &&
                         std::isfinite(corner[k].z);
            }
            if (finite) triangles.insert(triangles.end(), corner, corner + 3);
        }
    }
    vertexCount_ = GLsizei(triangles.size());
    vertices_ = gl::createBuffer();
    glNamedBufferStorage(vertices_.id(), GLsizeiptr(std::max<std::size_t>(triangles.size(), 1) * sizeof(glm::vec3)),
                         triangles.empty() ? nullptr : triangles.data(), 0);
    const glm::mat4 identity(1.0f);
    const std::uint32_t drawIndex = 0;
    transform_ = gl::createBuffer();
    glNamedBufferStorage(transform_.id(), sizeof identity, &identity, 0);
    drawIndex_ = gl::createBuffer();
    glNamedBufferStorage(drawIndex_.id(), sizeof drawIndex, &drawIndex, 0);
    vao_ = gl::createVertexArray();
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(glm::vec3));
    glEnableVertexArrayAttrib(vao_.id(), 0);
    glVertexArrayAttribFormat(vao_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao_.id(), 0, 0);
    // The draw index as GpuScene feeds it (an instanced attribute), always 0: the identity above.
    glVertexArrayVertexBuffer(vao_.id(), 1, drawIndex_.id(), 0, sizeof drawIndex);
    glVertexArrayBindingDivisor(vao_.id(), 1, 1);
    glEnableVertexArrayAttrib(vao_.id(), kDrawIndexAttribute);
    glVertexArrayAttribIFormat(vao_.id(), kDrawIndexAttribute, 1, GL_UNSIGNED_INT, 0);
    glVertexArrayAttribBinding(vao_.id(), kDrawIndexAttribute, 1);
}

BareDrawTiming BareDepthDraw::time(const glm::dmat4& lightViewProjection, int resolution, DepthFormat format,
                                   int maxTextureSize, int frames) {
    BareDrawTiming result;
    result.resolution = resolution;
    result.format = format;
    result.lightViewProjection = lightViewProjection;
    if (std::string error = map_.ensure(resolution, format, maxTextureSize); !error.empty()) {
        result.error = error;
        return result;
    }
    const glm::mat4 viewProjection(lightViewProjection);
    const RepeatedTiming timing = timeRepeated(frames, [&](std::vector<double>& ms) -> std::string {
        timer_.begin(TimedPass::Shadow);
        glBindFramebuffer(GL_FRAMEBUFFER, map_.framebuffer());
        glViewport(0, 0, resolution, resolution);
        glDepthMask(GL_TRUE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glClearDepth(1.0);
        glClear(GL_DEPTH_BUFFER_BIT);
        glUseProgram(program_.id());
        glUniformMatrix4fv(lightViewProjection_, 1, GL_FALSE, glm::value_ptr(viewProjection));
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDrawTransformsBinding, transform_.id());
        glBindVertexArray(vao_.id());
        glDrawArrays(GL_TRIANGLES, 0, vertexCount_);
        timer_.end(TimedPass::Shadow);
        ms = {timer_.latestMilliseconds(TimedPass::Shadow, true).value_or(0.0)};
        return "";
    }, timer_.source() == TimingSource::GpuQueries ? kGpuWarmUpMs : 0.0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    result.ms = timing.medianMs.empty() ? 0.0 : timing.medianMs[0];
    result.wallMsPerDraw = timing.wallMsPerRun;
    result.ok = true;
    return result;
}

}  // namespace shadowlab
