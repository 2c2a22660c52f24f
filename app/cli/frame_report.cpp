#include "cli/frame_report.h"

#include "shadow/shadow_map.h"

#include <iomanip>
#include <sstream>

namespace shadowlab::cli {

namespace {

std::string milliseconds(const PassStats& pass) {
    if (!pass.ran) return "not run";
    if (!pass.milliseconds) return "ran (time unavailable)";
    std::ostringstream s;
    s << std::fixed << std::setprecision(3) << *pass.milliseconds << " ms";
    return s.str();
}

}  // namespace

void printFrameReport(std::ostream& out, const Scene& scene, const GlInfo& info, const FrameStats& stats) {
    out << "scene: " << scene.name << " (" << stats.sceneTriangles << " triangles)\n";
    out << "gl: " << info.renderer << "; timing: " << stats.timingSource << "\n";
    out << "shadow map: " << stats.shadowMapResolution << "² " << depthFormatName(stats.shadowMapFormat) << ", "
        << stats.shadowMapBytes / 1024 << " KiB" << (stats.shadowMapReallocated ? " (allocated)" : "") << "\n";
    out << "shadow pass: " << milliseconds(stats.shadowPass) << " — " << stats.shadowPass.reason << "; "
        << stats.castersDrawn << " casters drawn (" << stats.alphaTestedCasters << " alpha-tested), "
        << stats.castersSkipped << " outside the light's volume skipped, " << stats.shadowTriangles
        << " triangles\n";
    out << "main pass: " << milliseconds(stats.mainPass) << "; variants:";
    for (const std::string& v : stats.mainVariants) out << " [" << v << "]";
    out << "\n";
    out << std::setprecision(4) << "light: " << stats.lightSource << "; "
        << (stats.light.perspective ? "spot" : "directional") << ", near "
        << stats.light.nearPlane << ", far " << stats.light.farPlane << ", texel " << stats.bias.texelWorldSize
        << " world units\n";
    out << "bias (glPolygonOffsetClamp, at this scene's receivers):\n";
    for (const std::string& line : describeBias(stats.bias))
        out << "  " << line << "\n";
}

}  // namespace shadowlab::cli
