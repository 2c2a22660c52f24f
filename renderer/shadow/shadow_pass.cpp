#include "shadow/shadow_pass.h"

#include "frame/face_culling.h"
#include "gl/program.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace shadowlab {

namespace {

void setPolygonOffset(float slopeScaled, float constant, float clamp, bool hasClamp) {
    // D3D: Bias = DepthBias * r + SlopeScaledDepthBias * MaxDepthSlope, clamped to DepthBiasClamp. GL's polygon
    // offset is the same formula: factor = slope scale, units = constant (in units of r). Callers negate all three
    // for reversed-Z, where away from the light is toward 0 (a negative clamp bounds a negative offset).
    if (slopeScaled == 0.0f && constant == 0.0f) {
        glDisable(GL_POLYGON_OFFSET_FILL);
        return;
    }
    glEnable(GL_POLYGON_OFFSET_FILL);
    if (hasClamp && glPolygonOffsetClamp)
        glPolygonOffsetClamp(slopeScaled, constant, clamp);
    else if (hasClamp && glPolygonOffsetClampEXT)
        glPolygonOffsetClampEXT(slopeScaled, constant, clamp);
    else
        glPolygonOffset(slopeScaled, constant);
}

}  // namespace

ShadowPass::CasterProgram::CasterProgram(gl::Program built) : program(std::move(built)) {
    const GLuint p = program.id();
    lightViewProjection = glGetUniformLocation(p, "uLightViewProjection");
    model = glGetUniformLocation(p, "uModel");
    uvTransform = glGetUniformLocation(p, "uUvTransform");
    alphaFactor = glGetUniformLocation(p, "uAlphaFactor");
    alphaCutoff = glGetUniformLocation(p, "uAlphaCutoff");
    baseColor = glGetUniformLocation(p, "uBaseColorTexture");
}

ShadowPass::ShadowPass()
    : depthOnly_(gl::buildProgram({{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"}}, {})),
      alphaFactorOnly_(gl::buildProgram(
          {{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"}, {GL_FRAGMENT_SHADER, "shadow_alpha.frag.glsl"}},
          {"ALPHA_MASK"})),
      alphaTextured_(gl::buildProgram(
          {{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"}, {GL_FRAGMENT_SHADER, "shadow_alpha.frag.glsl"}},
          {"ALPHA_MASK", "BASE_COLOR_TEXTURE"})),
      hasOffsetClamp_(glPolygonOffsetClamp != nullptr || glPolygonOffsetClampEXT != nullptr) {}

void clearShadowMap(const ShadowMap& map, bool reversedZ) {
    glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    glDepthMask(GL_TRUE);
    glClearDepth(reversedZ ? 0.0 : 1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
}

CasterSphere casterSphere(const GpuDraw& draw) {
    return {glm::dvec3(draw.boundsCenter), double(draw.boundsRadius), draw.hasFiniteBounds};
}

std::vector<CasterSphere> casterSpheres(const GpuScene& scene) {
    std::vector<CasterSphere> spheres;
    for (const GpuDraw& draw : scene.draws())
        if (draw.casts) spheres.push_back(casterSphere(draw));
    return spheres;
}

ShadowPassCounts ShadowPass::run(const GpuScene& scene, const LightSpace& light, const ShadowMapSettings& shadow,
                                 bool depthClamp, ShadowMap& map, const CasterSelection& selection) {
    ShadowPassCounts counts;
    glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    glViewport(0, 0, map.resolution(), map.resolution());
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    // Reversed-Z: the light's projection maps near to 1 and far to 0 in zero-to-one clip depth (light_space.cpp).
    const bool reversed = light.reversedZ;
    if (reversed) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glDepthFunc(reversed ? GL_GREATER : GL_LESS);
    glClearDepth(reversed ? 0.0 : 1.0);
    if (selection.scissor) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(selection.scissor->x0, selection.scissor->y0, selection.scissor->x1 - selection.scissor->x0,
                  selection.scissor->y1 - selection.scissor->y0);
    }
    if (selection.clear) glClear(GL_DEPTH_BUFFER_BIT);
    if (depthClamp)
        glEnable(GL_DEPTH_CLAMP);
    else
        glDisable(GL_DEPTH_CLAMP);
    const float toward = reversed ? -1.0f : 1.0f;  // the bias keys push away from the light in both conventions
    setPolygonOffset(toward * shadow.slopeScaledDepthBias, toward * shadow.depthBias, toward * shadow.depthBiasClamp,
                     hasOffsetClamp_);

    const glm::mat4 lightViewProjection(light.viewProjection());
    std::set<GLuint> prepared;  // programs whose per-pass uniforms are set
    scene.bind();
    const Scene& model = scene.scene();
    const std::size_t drawCount = selection.draws ? selection.draws->size() : scene.draws().size();
    for (std::size_t k = 0; k < drawCount; ++k) {
        const GpuDraw& draw = scene.draws()[selection.draws ? (*selection.draws)[k] : k];
        if (!draw.casts) continue;  // its node is excluded (casters.excluded)
        if (!casterInVolume(casterSphere(draw), light)) {
            ++counts.castersSkipped;
            continue;
        }
        const Material* material = draw.material >= 0 ? &model.materials[std::size_t(draw.material)] : nullptr;
        const bool alphaTested = material && material->alphaMode == AlphaMode::Mask;
        const GLuint texture = alphaTested ? scene.materialTexture(draw.material) : 0;
        const CasterProgram& caster = !alphaTested ? depthOnly_ : texture ? alphaTextured_ : alphaFactorOnly_;
        glUseProgram(caster.program.id());
        if (prepared.insert(caster.program.id()).second) {
            glUniformMatrix4fv(caster.lightViewProjection, 1, GL_FALSE, glm::value_ptr(lightViewProjection));
            glUniform1i(caster.baseColor, 1);
        }
        glUniformMatrix4fv(caster.model, 1, GL_FALSE, glm::value_ptr(draw.model));
        if (alphaTested) {
            ++counts.alphaTestedCasters;
            glUniformMatrix3fv(caster.uvTransform, 1, GL_FALSE, glm::value_ptr(material->uvTransform));
            glUniform1f(caster.alphaFactor, material->baseColorFactor.a);
            glUniform1f(caster.alphaCutoff, material->alphaCutoff);
            if (texture) glBindTextureUnit(1, texture);
        }
        applyShadowFaceCulling(shadow.cullMode, material, draw.mirrored);
        glDrawElementsBaseVertex(GL_TRIANGLES, draw.indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(draw.firstIndexByte), draw.baseVertex);
        ++counts.castersDrawn;
        counts.trianglesDrawn += std::size_t(draw.indexCount / 3);
    }
    resetFaceCulling();
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_CLAMP);
    if (reversed) glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glDepthFunc(GL_LESS);
    return counts;
}

}  // namespace shadowlab
