#include "shading/shader_variants.h"

#include "gl/program.h"

namespace shadowlab {

std::vector<std::string> MainVariantKey::defines() const {
    std::vector<std::string> d;
    switch (filter) {
        case FilterKind::Point: d.push_back("FILTER_POINT"); break;
        case FilterKind::Hardware2x2: d.push_back("FILTER_HARDWARE_2X2"); break;
        case FilterKind::Pcf:
            d.push_back("FILTER_PCF");
            d.push_back("PCF_KERNEL " + std::to_string(kernel));
            break;
        case FilterKind::Poisson: d.push_back("FILTER_POISSON"); break;
    }
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

GLuint MainVariantCache::program(const MainVariantKey& key) {
    auto it = programs_.find(key);
    if (it == programs_.end())
        it = programs_
                 .emplace(key, gl::buildProgram({{GL_VERTEX_SHADER, "main.vert.glsl"},
                                                 {GL_FRAGMENT_SHADER, "main.frag.glsl"}},
                                                key.defines()))
                 .first;
    return it->second.id();
}

}  // namespace shadowlab
