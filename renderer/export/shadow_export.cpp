#include "light/scene_lights.h"
#include "export/shadow_export.h"

#include "scene/scene.h"

#include <cmath>

namespace shadowlab {

std::optional<ExportFormat> parseExportFormat(const std::string& name) {
    if (name == "d3d12") return ExportFormat::D3D12;
    if (name == "d3d11") return ExportFormat::D3D11;
    if (name == "vulkan") return ExportFormat::Vulkan;
    if (name == "gl") return ExportFormat::GL;
    if (name == "json") return ExportFormat::Json;
    return std::nullopt;
}

const char* exportFormatChoices() { return "d3d12|d3d11|vulkan|gl|json"; }

ShadowExport makeShadowExport(const Settings& settings, const LightSpace& light, const std::string& sceneLabel) {
    ShadowExport e;
    e.sceneLabel = sceneLabel;
    e.shadow = settings.lights[0].shadow;
    e.sampler = settings.sampler;
    e.filter = settings.filter;
    e.depthClamp = settings.lights[0].depthClampApplies();
    e.perspective = light.perspective;
    e.reversedZ = light.reversedZ;
    const ShadowMapSettings& s = settings.lights[0].shadow;
    e.biasSign = light.reversedZ ? -1.0f : 1.0f;
    const auto signedValue = [&](float v) { return v == 0.0f ? 0.0f : e.biasSign * v; };  // no "-0.0f" in snippets
    e.rasterDepthBias = signedValue(s.depthBias);
    e.rasterSlopeScaledDepthBias = signedValue(s.slopeScaledDepthBias);
    e.rasterDepthBiasClamp = signedValue(s.depthBiasClamp);
    e.borderStored = conventionBorderDepth(settings.sampler.borderDepth, light.reversedZ);
    switch (settings.lights[0].shadow.format) {
        case DepthFormat::D16: e.depthBits = 16; e.floatDepth = false; break;
        case DepthFormat::D24: e.depthBits = 24; e.floatDepth = false; break;
        case DepthFormat::D32F: e.depthBits = 32; e.floatDepth = true; break;
    }
    // UNORM: r = 1 / (2^n - 1). Float: r = 2^(exponent(max depth of the primitive) - 23), 2^-24 for depths in [0.5, 1).
    e.depthStep = depthStepAt(settings.lights[0].shadow.format, 0.75);  // D32F: the step for depths in [0.5, 1)
    e.d3dDepthBias = int(std::lround(double(e.rasterDepthBias)));
    e.d3dDepthBiasError = double(e.d3dDepthBias) - double(e.rasterDepthBias);
    e.texelWorldSize = light.texelWorldSize;
    e.normalOffsetWorld = double(settings.lights[0].shadow.normalOffset) * light.texelWorldSize;
    e.nearPlane = light.nearPlane;
    e.farPlane = light.farPlane;
    e.linearCompare = settings.filter.kind == FilterKind::Hardware2x2 || settings.filter.kind == FilterKind::Poisson;
    return e;
}

std::optional<ShadowExport> exportForScene(const Settings& requested, const Scene& scene, const std::string& sceneLabel,
                                           std::string& error) {
    if (const std::vector<std::string> problems = requested.validate(); !problems.empty()) {
        error = problems.front();
        return std::nullopt;
    }
    Settings settings = requested;
    settings = withEffectiveLights(requested, scene);
    // The renderer's origin (the scene's centre); the light's sizes do not depend on it.
    const glm::dvec3 origin = scene.bounds.empty ? glm::dvec3(0.0) : glm::dvec3(scene.bounds.center());
    const std::optional<LightSpace> light = buildLightSpace(settings, scene.bounds, origin, error);
    if (!light) return std::nullopt;
    ShadowExport e = makeShadowExport(settings, *light, sceneLabel);
    e.bias = biasReport(settings.lights[0].shadow, settings.lights[0].shadow.format, *light, receiverDepths(scene, *light, origin));
    return e;
}

}  // namespace shadowlab
