#include "context/gl_info.h"

#include "gl/gl.h"

namespace shadowlab {

namespace {

std::string glString(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

GlInfo queryGlInfo() {
    GlInfo info;
    info.vendor = glString(GL_VENDOR);
    info.renderer = glString(GL_RENDERER);
    info.version = glString(GL_VERSION);
    info.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &info.maxTextureSize);
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &info.maxArrayTextureLayers);
    glGetIntegerv(GL_MAX_SAMPLES, &info.maxSamples);
    info.polygonOffsetClamp = glPolygonOffsetClamp != nullptr || glPolygonOffsetClampEXT != nullptr;
    info.clipControl = glClipControl != nullptr;
    for (const char* soft : {"llvmpipe", "softpipe", "swrast", "SwiftShader", "lavapipe"})
        if (info.renderer.find(soft) != std::string::npos) info.softwareRasterizer = true;
    return info;
}

}  // namespace shadowlab
