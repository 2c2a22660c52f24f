#include "shading/shader_variants.h"

#include "gl/program.h"
#include "shading/filter_taps.h"

namespace shadowlab {

std::vector<std::string> MainVariantKey::defines() const {
    std::vector<std::string> d = filterDefines(filter, kernel);
    switch (view) {
        case ViewMode::Lit: d.push_back("VIEW_LIT"); break;
        case ViewMode::Shadow: d.push_back("VIEW_SHADOW"); break;
        case ViewMode::LightDepth: d.push_back("VIEW_LIGHT_DEPTH"); break;
    }
    if (perspectiveLight) d.push_back("LIGHT_PERSPECTIVE");
    if (normalOffset) d.push_back("NORMAL_OFFSET");
    if (alphaMask) d.push_back("ALPHA_MASK");
    if (alphaMask && alphaTexture) d.push_back("BASE_COLOR_TEXTURE");
    return d;
}

std::string MainVariantKey::name() const {
    std::string joined;
    for (const std::string& d : defines()) joined += (joined.empty() ? "" : " ") + d;
    return joined;
}

namespace {

MainUniforms locateUniforms(GLuint p) {
    const auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
    return {at("uViewProjection"),     at("uModel"),          at("uNormalMatrix"),      at("uUvTransform"),
            at("uLightViewProjection"), at("uShadowMap"),      at("uLightDirection"),    at("uLightPosition"),
            at("uCameraPosition"),     at("uShadowTexel"),    at("uBaseColor"),         at("uLightIntensity"),
            at("uAmbient"),            at("uLightDepthRange"), at("uNormalOffsetTexels"), at("uTexelWorldSize"),
            at("uSpotCosHalfAngle"),   at("uPoissonRadiusTexels"), at("uAlphaFactor"),   at("uAlphaCutoff"),
            at("uBaseColorTexture")};
}

}  // namespace

const MainProgram& MainVariantCache::program(const MainVariantKey& key) {
    auto it = programs_.find(key);
    if (it == programs_.end()) {
        gl::Program program = gl::buildProgram(
            {{GL_VERTEX_SHADER, "main.vert.glsl"}, {GL_FRAGMENT_SHADER, "main.frag.glsl"}}, key.defines());
        const MainUniforms uniforms = locateUniforms(program.id());
        it = programs_.emplace(key, MainProgram{std::move(program), uniforms, key.name()}).first;
    }
    return it->second;
}

}  // namespace shadowlab
