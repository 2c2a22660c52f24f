#include "shading/shader_variants.h"

#include "gl/program.h"
#include "shading/cascade_tints.h"
#include "shading/filter_taps.h"
#include "shading/filters/filter_technique.h"

#include <cctype>

namespace shadowlab {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

std::vector<std::string> MainVariantKey::defines() const {
    FilterSettings filterSettings;
    filterSettings.kind = filter;
    filterSettings.kernel = kernel;
    std::vector<std::string> d = filterDefines(filterSettings);
    switch (view) {
        case ViewMode::Lit: d.push_back("VIEW_LIT"); break;
        case ViewMode::Shadow: d.push_back("VIEW_SHADOW"); break;
        case ViewMode::LightDepth: d.push_back("VIEW_LIGHT_DEPTH"); break;
        case ViewMode::Cascades:
            d.push_back("VIEW_CASCADES");
            d.push_back(cascadeTintsDefine());  // the colours the editor's lists and frusta use too
            break;
        case ViewMode::TexelDensity: d.push_back("VIEW_TEXEL_DENSITY"); break;
    }
    d.push_back("DIR_LIGHTS " + std::to_string(lights.directional));
    d.push_back("DIR_CASTERS " + std::to_string(lights.directionalCasters));
    d.push_back("SPOT_LIGHTS " + std::to_string(lights.spot));
    d.push_back("SPOT_CASTERS " + std::to_string(lights.spotCasters));
    d.push_back("POINT_LIGHTS " + std::to_string(lights.point));
    d.push_back("POINT_CASTERS " + std::to_string(lights.pointCasters));
    d.push_back("MAP_ARRAYS_2D " + std::to_string(lights.mapArrays2D));
    d.push_back("MAP_ARRAYS_CUBE " + std::to_string(lights.mapArraysCube));
    d.push_back("CASCADES " + std::to_string(lights.cascades));
    if (normalOffset) d.push_back("NORMAL_OFFSET");
    if (receiverPlane) d.push_back("RECEIVER_PLANE");
    if (receiverPlane && !filterTechnique(filter).bilinear) d.push_back("FILTER_NEAREST");
    if (alphaMask) d.push_back("ALPHA_MASK");
    if (alphaMask && alphaTexture) d.push_back("BASE_COLOR_TEXTURE");
    return d;
}

std::string MainVariantKey::name() const {
    std::string joined;
    for (std::string d : defines()) {
        if (d.starts_with("FILTER_TAP_OFFSETS") || d.starts_with("FILTER_GRID_RADIUS")) continue;  // the numbers follow from the filter, said by FILTER_TAPS
        if (d.starts_with("CASCADE_TINTS")) continue;  // fixed colours, said by VIEW_CASCADES
        if (d.starts_with("FILTER_TAPS")) d = "FILTER_" + upper(filterTechnique(filter).name) +
                                              (filter == FilterKind::Pcf ? " PCF_KERNEL " + std::to_string(kernel) : "") +
                                              " " + d;
        joined += (joined.empty() ? "" : " ") + d;
    }
    return joined;
}

namespace {

MainUniforms locateUniforms(GLuint p) {
    const auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
    return {at("uViewProjection"), at("uModel"),          at("uNormalMatrix"), at("uUvTransform"),
            at("uMaps2D[0]"),      at("uMapsCube[0]"),    at("uCameraPosition"), at("uBaseColor"),
            at("uAmbient"),        at("uFilterScale"),    at("uAlphaFactor"),  at("uAlphaCutoff"),
            at("uBaseColorTexture"), at("uCameraForward"), at("uPixelPerDepth"), at("uCascadeEye"),
            at("uCascadeForward")};
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
