#include "shading/shader_variants.h"

#include "gl/program.h"
#include "shading/filters/filter_technique.h"

namespace shadowlab {

namespace {

MainUniforms locateUniforms(GLuint p) {
    const auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
    return {at("uViewProjection"), at("uModel"),          at("uNormalMatrix"), at("uUvTransform"),
            at("uMaps2D[0]"),      at("uMapsCube[0]"),    at("uCameraPosition"), at("uBaseColor"),
            at("uAmbient"),        at("uFilterScale"),    at("uAlphaFactor"),  at("uAlphaCutoff"),
            at("uBaseColorTexture"), at("uCameraForward"), at("uPixelPerDepth"), at("uCascadeEye"),
            at("uCascadeForward"), at("uTechnique"),     at("uDepth2D[0]"),   at("uDepthCube[0]")};
}

}  // namespace

const MainProgram& MainVariantCache::program(const MainVariantKey& key) {
    auto it = programs_.find(key);
    if (it == programs_.end()) {
        // A moments technique's lookup is its own file: the variant includes exactly that one.
        const MomentTechnique* moments = filterTechnique(key.filter).moments;
        gl::IncludeAliases aliases;
        if (moments) aliases["alias:technique"] = moments->glslFile;
        if (const OwnLookup* own = filterTechnique(key.filter).ownLookup) aliases["alias:lookup"] = own->glslFile;
        gl::Program program = gl::buildProgram(
            {{GL_VERTEX_SHADER, "main.vert.glsl"}, {GL_FRAGMENT_SHADER, "main.frag.glsl"}}, key.defines(), aliases);
        const MainUniforms uniforms = locateUniforms(program.id());
        it = programs_.emplace(key, MainProgram{std::move(program), uniforms, key.name()}).first;
    }
    return it->second;
}

}  // namespace shadowlab
