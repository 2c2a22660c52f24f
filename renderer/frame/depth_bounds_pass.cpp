#include "frame/depth_bounds_pass.h"

#include "frame/face_culling.h"
#include "gl/program.h"
#include "views/depth_bounds.h"

#include <glm/gtc/type_ptr.hpp>

#include <set>

namespace shadowlab {

DepthBoundsPass::Program::Program(gl::Program built) : program(std::move(built)) {
    const GLuint p = program.id();
    viewProjection = glGetUniformLocation(p, "uLightViewProjection");
    model = glGetUniformLocation(p, "uModel");
    uvTransform = glGetUniformLocation(p, "uUvTransform");
    alphaFactor = glGetUniformLocation(p, "uAlphaFactor");
    alphaCutoff = glGetUniformLocation(p, "uAlphaCutoff");
    baseColor = glGetUniformLocation(p, "uBaseColorTexture");
}

DepthBoundsPass::DepthBoundsPass()
    : opaque_(gl::buildProgram({{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"}}, {})),
      alphaFactor_(gl::buildProgram(
          {{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"}, {GL_FRAGMENT_SHADER, "shadow_alpha.frag.glsl"}},
          {"ALPHA_MASK"})),
      alphaTextured_(gl::buildProgram(
          {{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"}, {GL_FRAGMENT_SHADER, "shadow_alpha.frag.glsl"}},
          {"ALPHA_MASK", "BASE_COLOR_TEXTURE"})) {}

void DepthBoundsPass::drawDepth(const GpuScene& scene, const glm::dmat4& viewProjection, RenderTarget& target) {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glViewport(0, 0, target.width(), target.height());
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    const glm::mat4 vp(viewProjection);
    std::set<GLuint> prepared;
    scene.bind();
    const Scene& model = scene.scene();
    // Every draw, casting or not: what the camera sees is what receives.
    for (const GpuDraw& draw : scene.draws()) {
        const Material* material = draw.material >= 0 ? &model.materials[std::size_t(draw.material)] : nullptr;
        const bool alphaTested = material && material->alphaMode == AlphaMode::Mask;
        const GLuint texture = alphaTested ? scene.materialTexture(draw.material) : 0;
        const Program& p = !alphaTested ? opaque_ : texture ? alphaTextured_ : alphaFactor_;
        glUseProgram(p.program.id());
        if (prepared.insert(p.program.id()).second) {
            glUniformMatrix4fv(p.viewProjection, 1, GL_FALSE, glm::value_ptr(vp));
            glUniform1i(p.baseColor, 1);
        }
        glUniformMatrix4fv(p.model, 1, GL_FALSE, glm::value_ptr(draw.model));
        if (alphaTested) {
            glUniformMatrix3fv(p.uvTransform, 1, GL_FALSE, glm::value_ptr(material->uvTransform));
            glUniform1f(p.alphaFactor, material->baseColorFactor.a);
            glUniform1f(p.alphaCutoff, material->alphaCutoff);
            if (texture) glBindTextureUnit(1, texture);
        }
        applyViewFaceCulling(material, draw.mirrored);
        glDrawElementsBaseVertex(GL_TRIANGLES, draw.indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(draw.firstIndexByte), draw.baseVertex);
    }
    resetFaceCulling();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glUseProgram(0);
}

ViewDepths DepthBoundsPass::toViewDepths(const std::optional<WrittenDepths>& written,
                                         const glm::dmat4& projection) const {
    if (!written) return {1.0, 0.0};  // nothing drawn: farthest < nearest says "nothing seen"
    return {viewDepthOfWindowDepth(projection, written->min), viewDepthOfWindowDepth(projection, written->max)};
}

ViewDepths DepthBoundsPass::measureNow(const GpuScene& scene, const glm::dmat4& viewProjection,
                                       const glm::dmat4& projection, RenderTarget& target) {
    drawDepth(scene, viewProjection, target);
    reduction_.dispatch(target.depthTexture(), target.width(), target.height(), false);
    return toViewDepths(reduction_.read(), projection);
}

void DepthBoundsPass::reduceMainDepth(const glm::dmat4& projection, RenderTarget& target) {
    reduction_.dispatch(target.depthTexture(), target.width(), target.height(), false);
    pendingProjection_ = projection;
}

std::optional<ViewDepths> DepthBoundsPass::collect() {
    if (!reduction_.pending()) return std::nullopt;
    return toViewDepths(reduction_.read(), pendingProjection_);
}

}  // namespace shadowlab
