#include "shading/main_pass.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace shadowlab {

namespace {

constexpr GLuint kShadowMapUnit = 0;
constexpr GLuint kBaseColorUnit = 1;

GLint uniform(GLuint program, const char* name) { return glGetUniformLocation(program, name); }

}  // namespace

std::set<std::string> MainPass::run(const MainPassInput& in, RenderTarget& target) {
    const Settings& settings = *in.settings;
    const LightSpace& light = *in.light;
    const Scene& scene = in.scene->scene();
    std::set<std::string> used;

    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glViewport(0, 0, target.width(), target.height());
    glClearColor(0.10f, 0.11f, 0.13f, 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // two-sided: shading flips the normal on back faces
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glBindTextureUnit(kShadowMapUnit, in.shadowMap->texture());
    glBindSampler(kShadowMapUnit, in.shadowMap->compareSampler());

    const glm::mat4 viewProjection(in.viewProjection);
    const glm::mat4 lightViewProjection(light.viewProjection());
    const float texel = 1.0f / float(in.shadowMap->resolution());
    MainVariantKey base;
    base.filter = settings.filter.kind;
    base.kernel = settings.filter.kernel;
    base.view = settings.view;
    base.perspectiveLight = light.perspective;
    base.normalOffset = settings.shadow.normalOffset > 0.0f;

    in.scene->bind();
    for (const GpuDraw& draw : in.scene->draws()) {
        const Material* material = draw.material >= 0 ? &scene.materials[std::size_t(draw.material)] : nullptr;
        MainVariantKey key = base;
        key.alphaMask = material && material->alphaMode == AlphaMode::Mask;
        const GLuint alphaTexture = key.alphaMask ? in.scene->materialTexture(draw.material) : 0;
        key.alphaTexture = alphaTexture != 0;
        const GLuint program = variants_.program(key);
        used.insert(key.name());
        glUseProgram(program);

        glUniformMatrix4fv(uniform(program, "uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
        glUniformMatrix4fv(uniform(program, "uModel"), 1, GL_FALSE, glm::value_ptr(draw.model));
        glUniformMatrix3fv(uniform(program, "uNormalMatrix"), 1, GL_FALSE, glm::value_ptr(draw.normalMatrix));
        const glm::mat3 uvTransform = material ? material->uvTransform : glm::mat3(1.0f);
        glUniformMatrix3fv(uniform(program, "uUvTransform"), 1, GL_FALSE, glm::value_ptr(uvTransform));
        glUniformMatrix4fv(uniform(program, "uLightViewProjection"), 1, GL_FALSE, glm::value_ptr(lightViewProjection));
        glUniform1i(uniform(program, "uShadowMap"), GLint(kShadowMapUnit));
        glUniform3fv(uniform(program, "uLightDirection"), 1, glm::value_ptr(glm::vec3(light.direction)));
        glUniform3fv(uniform(program, "uLightPosition"), 1, glm::value_ptr(glm::vec3(light.position)));
        glUniform3fv(uniform(program, "uCameraPosition"), 1, glm::value_ptr(glm::vec3(in.cameraPosition)));
        glUniform2f(uniform(program, "uShadowTexel"), texel, texel);
        const glm::vec3 baseColor = material ? glm::vec3(material->baseColorFactor) : glm::vec3(0.8f);
        glUniform3fv(uniform(program, "uBaseColor"), 1, glm::value_ptr(baseColor));
        glUniform1f(uniform(program, "uLightIntensity"), settings.light.intensity);
        glUniform1f(uniform(program, "uAmbient"), settings.light.ambient);
        glUniform2f(uniform(program, "uLightDepthRange"), float(light.nearPlane), float(light.farPlane));
        if (key.normalOffset) {
            glUniform1f(uniform(program, "uNormalOffsetTexels"), settings.shadow.normalOffset);
            const double texelWorld = light.perspective ? 2.0 * light.tanHalfFov / light.resolution
                                                        : light.texelWorldSize;
            glUniform1f(uniform(program, "uTexelWorldSize"), float(texelWorld));
        }
        if (key.perspectiveLight)
            glUniform1f(uniform(program, "uSpotCosHalfAngle"), float(std::cos(std::atan(light.tanHalfFov))));
        if (key.filter == FilterKind::Poisson)
            glUniform1f(uniform(program, "uPoissonRadiusTexels"), settings.filter.poissonRadius);
        if (key.alphaMask) {
            glUniform1f(uniform(program, "uAlphaFactor"), material->baseColorFactor.a);
            glUniform1f(uniform(program, "uAlphaCutoff"), material->alphaCutoff);
            if (alphaTexture) {
                glBindTextureUnit(kBaseColorUnit, alphaTexture);
                glUniform1i(uniform(program, "uBaseColorTexture"), GLint(kBaseColorUnit));
            }
        }
        glFrontFace(draw.mirrored ? GL_CW : GL_CCW);
        glDrawElementsBaseVertex(GL_TRIANGLES, draw.indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(draw.firstIndexByte), draw.baseVertex);
    }
    glFrontFace(GL_CCW);
    glBindSampler(kShadowMapUnit, 0);
    return used;
}

}  // namespace shadowlab
