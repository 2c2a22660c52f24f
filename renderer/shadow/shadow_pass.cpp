#include "shadow/shadow_pass.h"

#include "frame/face_culling.h"

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

ShadowPass::ShadowPass() : hasOffsetClamp_(glPolygonOffsetClamp != nullptr || glPolygonOffsetClampEXT != nullptr) {}

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

CasterSelection castersInVolume(const GpuScene& scene, const LightSpace& light) {
    CasterSelection selection;
    const std::vector<GpuDraw>& draws = scene.draws();
    for (std::size_t d = 0; d < draws.size(); ++d) {
        if (!draws[d].casts) continue;  // its node is excluded (casters.excluded)
        if (casterInVolume(casterSphere(draws[d]), light))
            selection.draws.push_back(std::uint32_t(d));
        else
            ++selection.skipped;
    }
    return selection;
}

ShadowPassCounts ShadowPass::run(const GpuScene& scene, const LightSpace& light, const ShadowMapSettings& shadow,
                                 bool depthClamp, ShadowMap& map) {
    return run(scene, castersInVolume(scene, light), light, shadow, depthClamp, map);
}

ShadowPassCounts ShadowPass::run(const GpuScene& scene, const CasterSelection& casters, const LightSpace& light,
                                 const ShadowMapSettings& shadow, bool depthClamp, ShadowMap& map) {
    ShadowPassCounts counts;
    counts.castersSkipped = casters.skipped;
    glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer());
    glViewport(0, 0, map.resolution(), map.resolution());
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    // Reversed-Z: the light's projection maps near to 1 and far to 0 in zero-to-one clip depth (light_space.cpp).
    const bool reversed = light.reversedZ;
    if (reversed) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glDepthFunc(reversed ? GL_GREATER : GL_LESS);
    glClearDepth(reversed ? 0.0 : 1.0);
    if (casters.scissor) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(casters.scissor->x0, casters.scissor->y0, casters.scissor->x1 - casters.scissor->x0,
                  casters.scissor->y1 - casters.scissor->y0);
    }
    if (casters.clear) glClear(GL_DEPTH_BUFFER_BIT);
    if (depthClamp)
        glEnable(GL_DEPTH_CLAMP);
    else
        glDisable(GL_DEPTH_CLAMP);
    const float toward = reversed ? -1.0f : 1.0f;  // the bias keys push away from the light in both conventions
    setPolygonOffset(toward * shadow.slopeScaledDepthBias, toward * shadow.depthBias, toward * shadow.depthBiasClamp,
                     hasOffsetClamp_);

    const DepthCastersDrawn drawn =
        casters_.draw(scene, casters.draws, glm::mat4(light.viewProjection()),
                      [&](const Material* material, bool mirrored) {
                          return shadowFaceCullState(shadow.cullMode, material, mirrored);
                      });
    counts.castersDrawn = int(casters.draws.size());
    counts.alphaTestedCasters = drawn.alphaTested;
    counts.trianglesDrawn = drawn.triangles;
    counts.drawCalls = drawn.drawCalls;
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_CLAMP);
    if (reversed) glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glDepthFunc(GL_LESS);
    return counts;
}

}  // namespace shadowlab
