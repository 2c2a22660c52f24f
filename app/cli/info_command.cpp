#include "cli/info_command.h"

#include "context/gl_info.h"
#include "context/headless_context.h"
#include "scene/builtin_scenes.h"
#include "settings/shipped_data.h"

#include <iostream>

namespace shadowlab::cli {

int runInfo() {
    // First, and without GL: an install that cannot find its presets says so even where no context starts.
    const ShippedData& data = shippedData();
    if (data.dir.empty()) std::cout << "shipped data: none (" << data.problem << ")\n";
    else std::cout << "shipped data: " << data.dir.string() << "\n";
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
    return data.dir.empty() ? 1 : 0;
}

int runScenes() {
    for (const std::string& name : builtinSceneNames())
        std::cout << "builtin:" << name << "  " << builtinSceneDescription(name) << "\n";
    return 0;
}

}  // namespace shadowlab::cli
