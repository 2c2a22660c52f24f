#include "shading/main_pass.h"

#include "frame/face_culling.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace shadowlab {

namespace {

constexpr GLuint kShadowMapUnit = 0;
constexpr GLuint kBaseColorUnit = 1;

// Uniforms that are the same for every draw of a frame: set once per program per frame.
void setFrameUniforms(const MainUniforms& u, const MainPassInput& in, const MainVariantKey& key) {
    const Settings& settings = *in.settings;
    const LightSpace& light = *in.light;
    const float texel = 1.0f / float(in.shadowMap->resolution());
    glUniformMatrix4fv(u.viewProjection, 1, GL_FALSE, glm::value_ptr(glm::mat4(in.viewProjection)));
    glUniformMatrix4fv(u.lightViewProjection, 1, GL_FALSE, glm::value_ptr(glm::mat4(light.viewProjection())));
    glUniform1i(u.shadowMap, GLint(kShadowMapUnit));
    glUniform3fv(u.lightDirection, 1, glm::value_ptr(glm::vec3(light.direction)));
    glUniform3fv(u.lightPosition, 1, glm::value_ptr(glm::vec3(light.position)));
    glUniform3fv(u.cameraPosition, 1, glm::value_ptr(glm::vec3(in.cameraPosition)));
    glUniform2f(u.shadowTexel, texel, texel);
    glUniform1f(u.lightIntensity, settings.lights[0].intensity);
    glUniform1f(u.ambient, settings.ambient);
    glUniform2f(u.lightDepthRange, float(light.nearPlane), float(light.farPlane));
    if (key.normalOffset) {
        glUniform1f(u.normalOffsetTexels, settings.lights[0].shadow.normalOffset);
        // Spot: the texel's world size grows with distance, so the shader multiplies by its depth.
        const double texelWorld = light.perspective ? 2.0 * light.tanHalfFov / light.resolution : light.texelWorldSize;
        glUniform1f(u.texelWorldSize, float(texelWorld));
    }
    if (key.perspectiveLight) glUniform1f(u.spotCosHalfAngle, float(std::cos(std::atan(light.tanHalfFov))));
    if (key.filter == FilterKind::Poisson) glUniform1f(u.poissonRadiusTexels, settings.filter.poissonRadius);
    if (key.alphaTexture) glUniform1i(u.baseColorTexture, GLint(kBaseColorUnit));
}

}  // namespace

std::set<std::string> MainPass::run(const MainPassInput& in, RenderTarget& target) {
    const Settings& settings = *in.settings;
    const Scene& scene = in.scene->scene();
    std::set<const MainProgram*> prepared;  // programs used this frame, their per-frame uniforms set

    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glViewport(0, 0, target.width(), target.height());
    glClearColor(0.10f, 0.11f, 0.13f, 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glBindTextureUnit(kShadowMapUnit, in.shadowMap->texture());
    glBindSampler(kShadowMapUnit, in.shadowMap->compareSampler());

    MainVariantKey base;
    base.filter = settings.filter.kind;
    base.kernel = settings.filter.kernel;
    base.view = settings.view;
    base.perspectiveLight = in.light->perspective;
    base.normalOffset = settings.lights[0].shadow.normalOffset > 0.0f;

    in.scene->bind();
    for (const GpuDraw& draw : in.scene->draws()) {
        const Material* material = draw.material >= 0 ? &scene.materials[std::size_t(draw.material)] : nullptr;
        MainVariantKey key = base;
        key.alphaMask = material && material->alphaMode == AlphaMode::Mask;
        const GLuint alphaTexture = key.alphaMask ? in.scene->materialTexture(draw.material) : 0;
        key.alphaTexture = alphaTexture != 0;
        const MainProgram& variant = variants_.program(key);
        const MainUniforms& u = variant.uniforms;
        glUseProgram(variant.program.id());
        if (prepared.insert(&variant).second) setFrameUniforms(u, in, key);

        glUniformMatrix4fv(u.model, 1, GL_FALSE, glm::value_ptr(draw.model));
        glUniformMatrix3fv(u.normalMatrix, 1, GL_FALSE, glm::value_ptr(draw.normalMatrix));
        const glm::mat3 uvTransform = material ? material->uvTransform : glm::mat3(1.0f);
        glUniformMatrix3fv(u.uvTransform, 1, GL_FALSE, glm::value_ptr(uvTransform));
        const glm::vec3 baseColor = material ? glm::vec3(material->baseColorFactor) : glm::vec3(0.8f);
        glUniform3fv(u.baseColor, 1, glm::value_ptr(baseColor));
        if (key.alphaMask) {
            glUniform1f(u.alphaFactor, material->baseColorFactor.a);
            glUniform1f(u.alphaCutoff, material->alphaCutoff);
            if (alphaTexture) glBindTextureUnit(kBaseColorUnit, alphaTexture);
        }
        // Single-sided back faces are not drawn; double-sided ones are, and shading flips their normal.
        applyViewFaceCulling(material, draw.mirrored);
        glDrawElementsBaseVertex(GL_TRIANGLES, draw.indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(draw.firstIndexByte), draw.baseVertex);
    }
    resetFaceCulling();
    glBindSampler(kShadowMapUnit, 0);
    std::set<std::string> used;
    for (const MainProgram* program : prepared) used.insert(program->name);
    return used;
}

}  // namespace shadowlab
