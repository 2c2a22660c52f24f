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
    // The file's cameras, by the index camera.sceneCamera takes.
    for (std::size_t i = 0; i < scene.cameras.size(); ++i)
        out << "  camera " << i << ": " << scene.cameras[i].name
            << (scene.cameras[i].orthographic ? " (orthographic)" : " (perspective)") << "\n";
    out << "gl: " << info.renderer << "; timing: " << stats.timingSource << "\n";
    out << "shadow maps: " << stats.shadowMapBytes / 1024 << " KiB in all" << (stats.shadowMapReallocated ? " (allocated)" : "")
        << "\n";
    out << "shadow pass: " << milliseconds(stats.shadowPass) << " — " << stats.shadowPass.reason << "; "
        << stats.castersDrawn << " casters drawn (" << stats.alphaTestedCasters << " alpha-tested), "
        << stats.castersSkipped << " outside the light's volume skipped, " << stats.shadowTriangles
        << " triangles, " << stats.shadowDrawCalls << " draw calls\n";
    out << "scene upload: " << (stats.sceneUpload.ran ? stats.sceneUpload.reason : "unchanged") << "\n";
    out << "main pass: " << milliseconds(stats.mainPass) << "; variants:";
    for (const std::string& v : stats.mainVariants) out << " [" << v << "]";
    out << "\n";
    using NamedPass = std::pair<const char*, const PassStats*>;
    for (const auto& [name, pass] : {NamedPass{"moments pass", &stats.momentsPass}, NamedPass{"blur pass", &stats.blurPass},
                                     NamedPass{"mips pass", &stats.mipsPass}})
        if (pass->ran || pass->reason.find("compares depth") == std::string::npos)
            out << name << ": " << milliseconds(*pass) << " — " << pass->reason << "\n";
    if (stats.depthBoundsPass.ran) {
        out << "depth bounds pass: " << milliseconds(stats.depthBoundsPass) << " — " << stats.depthBoundsPass.reason;
        if (stats.seenDepths && stats.seenDepths->farthest >= stats.seenDepths->nearest)
            out << "; seen depths " << stats.seenDepths->nearest << ".." << stats.seenDepths->farthest;
        else
            out << "; " << (stats.seenDepths ? "nothing seen" : "no depths yet");
        out << "\n";
    }
    // Every view with its own light, kind and map: no line describes "the" light when there are several.
    out << std::setprecision(4) << "lights: " << stats.lightSource << " (" << stats.lightCount << ")\n";
    const ShadowViewStats* first = nullptr;
    for (const ShadowViewStats& v : stats.views) {
        out << "  " << v.name << ": ";
        if (!v.hasView) {
            out << v.reason << "\n";
            continue;
        }
        if (!first) first = &v;
        const LightSpace& s = v.space;
        out << (s.cubeFace >= 0 ? "point (cube face)" : s.perspective ? "spot" : "directional") << ", map "
            << v.resolution << "² " << depthFormatName(v.format) << ", near " << s.nearPlane << ", far " << s.farPlane
            << (s.cubeFace >= 0 ? ", texel " : s.perspective ? ", texel at the scene centre " : ", texel ")
            << s.texelWorldSize << (s.cubeFace >= 0 ? " x distance" : "") << " world units";
        if (v.kind == ShadowViewKind::Cascade)
            out << ", holds depths " << v.slice.nearDepth << ".." << v.slice.farDepth << " from the camera"
                << (v.slice.blendStart < v.slice.farDepth ? " (fades into the next from " : "")
                << (v.slice.blendStart < v.slice.farDepth ? std::to_string(v.slice.blendStart) + ")" : "");
        out << "; " << (v.ran ? "rendered" : "skipped") << " (" << v.reason << ")\n";
    }
    if (!first) {
        out << "bias: no light casts a shadow\n";
        return;
    }
    // A cascaded light: every cascade (its texel sets the texel-relative terms, its receivers the depths).
    for (const FrameStats::ViewBias& v : stats.viewBias) {
        out << "bias of " << v.name
            << (stats.viewBias.size() > 1 ? "" : ", the first view") << " (glPolygonOffsetClamp, at "
            << (stats.viewBias.size() > 1 ? "the receivers in its volume" : "this scene's receivers") << "):\n";
        for (const std::string& line : describeBias(v.bias)) out << "  " << line << "\n";
    }
}

}  // namespace shadowlab::cli
