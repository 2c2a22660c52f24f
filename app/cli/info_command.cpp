#include "cli/info_command.h"

#include "context/gl_info.h"
#include "context/headless_context.h"
#include "scene/builtin_scenes.h"

#include <iostream>

namespace shadowlab::cli {

int runInfo() {
    try {
        HeadlessContext context;
        const GlInfo info = queryGlInfo();
        std::cout << "context: " << context.platform() << "\n"
                  << "GL_VENDOR: " << info.vendor << "\n"
                  << "GL_RENDERER: " << info.renderer << "\n"
                  << "GL_VERSION: " << info.version << "\n"
                  << "GLSL: " << info.glslVersion << "\n"
                  << "GL_MAX_TEXTURE_SIZE: " << info.maxTextureSize << " (largest shadow map)\n"
                  << "GL_MAX_SAMPLES: " << info.maxSamples << "\n"
                  << "polygon offset clamp (DepthBiasClamp): " << (info.polygonOffsetClamp ? "yes" : "no") << "\n"
                  << "glClipControl: " << (info.clipControl ? "yes" : "no") << "\n"
                  << "timing: "
                  << (info.softwareRasterizer ? "CPU around glFinish (software rasterizer: GPU timers unreliable)"
                                              : "GPU timer queries")
                  << "\n";
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

int runScenes() {
    for (const std::string& name : builtinSceneNames())
        std::cout << "builtin:" << name << "  " << builtinSceneDescription(name) << "\n";
    return 0;
}

}  // namespace shadowlab::cli
