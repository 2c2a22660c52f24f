#include "shading/main_pass.h"

#include "frame/face_culling.h"
#include "shading/filters/filter_technique.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shadowlab {

namespace {

constexpr GLuint kLightsBinding = 0;
constexpr GLuint kCascadesBinding = 1;

// std140 layout of LightData (shaders/shadow/light_data.glsl).
struct LightBlock {
    glm::mat4 viewProjection{1.0f};
    glm::vec4 position{0.0f};
    glm::vec4 direction{0.0f};
    glm::vec4 radiance{0.0f};
    glm::vec4 shadow{0.0f};
    glm::vec4 depth{0.0f};
    glm::vec4 views{0.0f};
};
static_assert(sizeof(LightBlock) == 160, "std140 LightData is 160 bytes");

// std140 layout of CascadeData (shaders/shadow/cascades.glsl).
struct CascadeBlock {
    glm::mat4 viewProjection{1.0f};
    glm::vec4 slice{0.0f};
};
static_assert(sizeof(CascadeBlock) == 80, "std140 CascadeData is 80 bytes");

CascadeBlock cascadeBlockOf(const MainPassCascade& c) {
    const ShadowView& v = *c.view;
    CascadeBlock b;
    b.viewProjection = glm::mat4(v.space.viewProjection());
    b.slice = glm::vec4(float(v.slice.farDepth), float(v.slice.blendStart), float(c.layer), float(v.space.texelWorldSize));
    return b;
}

// The order the shader walks lights in: directional, spot, point; casters first within each kind.
int bucket(const MainPassLight& l) {
    const int kind = l.settings->type == LightType::Directional ? 0 : l.settings->type == LightType::Spot ? 1 : 2;
    return kind * 2 + (l.space ? 0 : 1);
}

LightBlock blockOf(const MainPassLight& l, const glm::dvec3& origin) {
    const LightSettings& s = *l.settings;
    LightBlock b;
    const glm::dvec3 direction = glm::normalize(glm::dvec3(s.direction));
    b.position = glm::vec4(glm::vec3(glm::dvec3(s.position) - origin), s.range);
    b.direction = glm::vec4(glm::vec3(direction), 0.0f);
    b.radiance = glm::vec4(s.color, s.intensity);
    if (s.type == LightType::Spot)
        b.direction.w = float(std::cos(glm::radians(0.5 * double(std::clamp(s.spotConeDeg, 1.0f, 170.0f)))));
    if (l.space) {
        const LightSpace& space = *l.space;
        b.viewProjection = glm::mat4(space.viewProjection());
        b.position = glm::vec4(glm::vec3(space.position), s.range);
        if (s.type != LightType::Point) b.direction = glm::vec4(glm::vec3(space.direction), b.direction.w);
        // The cone the view was built with, as the one-light shader computed it.
        if (s.type == LightType::Spot) b.direction.w = float(std::cos(std::atan(space.tanHalfFov)));
        b.shadow = glm::vec4(float(l.mapArray), float(l.layer), 1.0f / float(space.resolution), s.shadow.normalOffset);
        // Directional: a texel's world size; spot and point: per unit of depth (the shader multiplies).
        const double texelWorld =
            space.perspective ? 2.0 * space.tanHalfFov / space.resolution : space.texelWorldSize;
        // w: flags, 1 = reversed-Z, 2 = receiver-plane bias (read only by RECEIVER_PLANE variants).
        const float flags = (space.reversedZ ? 1.0f : 0.0f) + (s.shadow.receiverPlaneBias ? 2.0f : 0.0f);
        b.depth = glm::vec4(float(space.nearPlane), float(space.farPlane), float(texelWorld), flags);
        b.views.z = lightSpread(s);  // the light's size, for a technique that softens by it (PCSS)
    }
    return b;
}

}  // namespace

MainPass::MainPass()
    : lightBuffer_(gl::createBuffer()), cascadeBuffer_(gl::createBuffer()), depthSampler_(gl::createSampler()) {
    // The maps read as depths (a technique's own lookup, PCSS): texel by texel, no comparison.
    glSamplerParameteri(depthSampler_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(depthSampler_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(depthSampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glSamplerParameteri(depthSampler_.id(), wrap, GL_CLAMP_TO_EDGE);
}

std::set<std::string> MainPass::run(const MainPassInput& in, RenderTarget& target) {
    const Settings& settings = *in.settings;
    const Scene& scene = in.scene->scene();
    std::set<const MainProgram*> prepared;  // programs used this frame, their per-frame uniforms set

    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glViewport(0, 0, target.width(), target.height());
    glClearColor(kClearColour[0], kClearColour[1], kClearColour[2], kClearColour[3]);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // PCF and bilinear taps at a cube edge read the neighbouring face

    // The light set, in the shader's order, and its uniform block.
    std::vector<MainPassLight> lights = in.lights;
    std::stable_sort(lights.begin(), lights.end(),
                     [](const MainPassLight& a, const MainPassLight& b) { return bucket(a) < bucket(b); });
    // The variant comes from the key table's variant-tagged keys (shading/variant_key.h); what is bound here must be
    // what it declares, or the shader would index past its arrays.
    const MainVariantKey& base = in.variant;
    std::vector<LightBlock> blocks;
    std::vector<CascadeBlock> cascadeBlocks;
    int casters = 0;
    for (const MainPassLight& l : lights) {
        const bool casts = l.space != nullptr;
        casters += casts;
        blocks.push_back(blockOf(l, in.renderOrigin));
        if (casts && !l.cascades.empty()) {
            // x: the light's first cascade in the Cascades block, y: how many (0: its one view).
            blocks.back().views.x = float(cascadeBlocks.size());
            blocks.back().views.y = float(l.cascades.size());
            for (const MainPassCascade& c : l.cascades) cascadeBlocks.push_back(cascadeBlockOf(c));
        }
    }
    const LightSetKey& declared = base.lights;
    if (int(blocks.size()) != declared.lights() ||
        casters != declared.directionalCasters + declared.spotCasters + declared.pointCasters ||
        int(cascadeBlocks.size()) != declared.cascades || int(in.maps2D.size()) != declared.mapArrays2D ||
        int(in.mapsCube.size()) != declared.mapArraysCube)
        throw std::logic_error("main pass: the frame binds " + std::to_string(blocks.size()) + " lights (" +
                               std::to_string(casters) + " casting), " + std::to_string(cascadeBlocks.size()) +
                               " cascades, " + std::to_string(in.maps2D.size()) + "+" +
                               std::to_string(in.mapsCube.size()) + " map arrays; its variant declares " +
                               base.name());
    if (!cascadeBlocks.empty()) {
        glNamedBufferData(cascadeBuffer_.id(), GLsizeiptr(cascadeBlocks.size() * sizeof(CascadeBlock)),
                          cascadeBlocks.data(), GL_STREAM_DRAW);
        glBindBufferBase(GL_UNIFORM_BUFFER, kCascadesBinding, cascadeBuffer_.id());
    }
    if (!blocks.empty()) {
        glNamedBufferData(lightBuffer_.id(), GLsizeiptr(blocks.size() * sizeof(LightBlock)), blocks.data(),
                          GL_STREAM_DRAW);
        glBindBufferBase(GL_UNIFORM_BUFFER, kLightsBinding, lightBuffer_.id());
    }

    // Texture units: the 2D arrays, then the cube arrays, then the base colour texture.
    std::vector<GLint> units2D, unitsCube;
    GLuint unit = 0;
    for (std::size_t a = 0; a < in.maps2D.size(); ++a) {
        glBindTextureUnit(unit, in.maps2D[a]);
        glBindSampler(unit, in.samplers2D.at(a));
        units2D.push_back(GLint(unit++));
    }
    for (std::size_t a = 0; a < in.mapsCube.size(); ++a) {
        glBindTextureUnit(unit, in.mapsCube[a]);
        glBindSampler(unit, in.samplersCube.at(a));
        unitsCube.push_back(GLint(unit++));
    }
    const FilterTechnique& technique = filterTechnique(settings.filter.kind);
    // A technique with a lookup of its own reads the maps' depths too: the same textures again, plain sampler.
    std::vector<GLint> depthUnits2D, depthUnitsCube;
    if (technique.ownLookup) {
        for (GLuint map : in.maps2D) {
            glBindTextureUnit(unit, map);
            glBindSampler(unit, depthSampler_.id());
            depthUnits2D.push_back(GLint(unit++));
        }
        for (GLuint map : in.mapsCube) {
            glBindTextureUnit(unit, map);
            glBindSampler(unit, depthSampler_.id());
            depthUnitsCube.push_back(GLint(unit++));
        }
    }
    const GLuint baseColorUnit = unit;
    const float filterScale = technique.scale(settings.filter);
    const glm::vec4 techniqueUniforms = technique.moments   ? technique.moments->uniforms(settings.filter)
                                        : technique.ownLookup ? technique.ownLookup->uniforms(settings.filter)
                                                              : glm::vec4(0.0f);

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
        if (prepared.insert(&variant).second) {
            // Uniforms that are the same for every draw of a frame: set once per program per frame.
            glUniformMatrix4fv(u.viewProjection, 1, GL_FALSE, glm::value_ptr(glm::mat4(in.viewProjection)));
            glUniform3fv(u.cameraPosition, 1, glm::value_ptr(glm::vec3(in.cameraPosition)));
            if (u.cameraForward >= 0) glUniform3fv(u.cameraForward, 1, glm::value_ptr(glm::vec3(in.cameraForward)));
            if (u.pixelPerDepth >= 0) glUniform1f(u.pixelPerDepth, float(in.pixelPerDepth));
            if (u.cascadeEye >= 0) glUniform3fv(u.cascadeEye, 1, glm::value_ptr(glm::vec3(in.cascadeEye)));
            if (u.cascadeForward >= 0)
                glUniform3fv(u.cascadeForward, 1, glm::value_ptr(glm::vec3(in.cascadeForward)));
            glUniform1f(u.ambient, settings.ambient);
            glUniform1f(u.filterScale, filterScale);
            if (u.technique >= 0) glUniform4fv(u.technique, 1, glm::value_ptr(techniqueUniforms));
            if (!units2D.empty()) glUniform1iv(u.maps2D, GLsizei(units2D.size()), units2D.data());
            if (!unitsCube.empty()) glUniform1iv(u.mapsCube, GLsizei(unitsCube.size()), unitsCube.data());
            if (!depthUnits2D.empty() && u.depth2D >= 0)
                glUniform1iv(u.depth2D, GLsizei(depthUnits2D.size()), depthUnits2D.data());
            if (!depthUnitsCube.empty() && u.depthCube >= 0)
                glUniform1iv(u.depthCube, GLsizei(depthUnitsCube.size()), depthUnitsCube.data());
            if (key.alphaTexture) glUniform1i(u.baseColorTexture, GLint(baseColorUnit));
        }

        glUniformMatrix4fv(u.model, 1, GL_FALSE, glm::value_ptr(draw.model));
        glUniformMatrix3fv(u.normalMatrix, 1, GL_FALSE, glm::value_ptr(draw.normalMatrix));
        const glm::mat3 uvTransform = material ? material->uvTransform : glm::mat3(1.0f);
        glUniformMatrix3fv(u.uvTransform, 1, GL_FALSE, glm::value_ptr(uvTransform));
        const glm::vec3 baseColor = material ? glm::vec3(material->baseColorFactor) : glm::vec3(0.8f);
        glUniform3fv(u.baseColor, 1, glm::value_ptr(baseColor));
        if (key.alphaMask) {
            glUniform1f(u.alphaFactor, material->baseColorFactor.a);
            glUniform1f(u.alphaCutoff, material->alphaCutoff);
            if (alphaTexture) glBindTextureUnit(baseColorUnit, alphaTexture);
        }
        // Single-sided back faces are not drawn; double-sided ones are, and shading flips their normal.
        applyViewFaceCulling(material, draw.mirrored);
        glDrawElementsBaseVertex(GL_TRIANGLES, draw.indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(draw.firstIndexByte), draw.baseVertex);
    }
    resetFaceCulling();
    for (GLuint u = 0; u < unit; ++u) glBindSampler(u, 0);
    std::set<std::string> used;
    for (const MainProgram* program : prepared) used.insert(program->name);
    return used;
}

}  // namespace shadowlab
