#include "light/scene_lights.h"
#include "export/shadow_export.h"
#include "light/blur_texel.h"

#include "scene/scene.h"
#include "views/shadow_view.h"
#include "settings/settings_fields.h"
#include "shading/filter_taps.h"
#include "shading/filters/filter_technique.h"
#include "shading/filters/moment_filter.h"

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

namespace {

ExportView viewOf(std::size_t index, LightType type, const LightSpace& light) {
    ExportView v;
    v.label = viewLabel(index, type, light.cubeFace);
    v.cubeFace = light.cubeFace;
    v.normalOffsetWorld = 0.0;  // set by the caller, who knows the setting
    v.viewProjection = light.viewProjection();
    v.nearPlane = light.nearPlane;
    v.farPlane = light.farPlane;
    v.texelWorldSize = light.texelWorldSize;
    return v;
}

// A moments technique's blur width in this view's texels, as the moments pass takes it.
void setBlur(ExportView& v, const FilterSettings& filter, const LightSpace& light) {
    if (!filterTechnique(filter.kind).moments) return;
    v.blurTexels = blurTexels(filter, blurTexelWorldSize(light), &v.blurClamped);
}

}  // namespace

std::string lightLabel(std::size_t index, LightType type) {
    return "light " + std::to_string(index) + " (" + lightTypeName(type) + ")";
}

std::string viewLabel(std::size_t index, LightType type, int cubeFace) {
    std::string label = lightLabel(index, type);
    if (cubeFace >= 0 && cubeFace < 6) label += std::string(" face ") + cubeFaces()[std::size_t(cubeFace)].name;
    return label;
}

ShadowExport makeShadowExport(const Settings& settings, std::size_t lightIndex, const LightSpace& light,
                              const std::string& sceneLabel) {
    const LightSettings& l = settings.lights.at(lightIndex);
    const ShadowMapSettings& s = l.shadow;
    ShadowExport e;
    e.sceneLabel = sceneLabel;
    e.lightIndex = lightIndex;
    e.lightType = l.type;
    e.label = lightLabel(lightIndex, l.type);
    e.views.push_back(viewOf(lightIndex, l.type, light));
    e.views.back().normalOffsetWorld = double(s.normalOffset) * light.texelWorldSize;
    setBlur(e.views.back(), settings.filter, light);
    e.lightPosition = light.position;
    e.lightDirection = light.direction;
    e.shadow = s;
    e.sampler = settings.sampler;
    e.filter = settings.filter;
    e.depthClamp = l.depthClampApplies();
    e.perspective = light.perspective;
    e.reversedZ = light.reversedZ;
    e.biasSign = light.reversedZ ? -1.0f : 1.0f;
    const auto signedValue = [&](float v) { return v == 0.0f ? 0.0f : e.biasSign * v; };  // no "-0.0f" in snippets
    e.rasterDepthBias = signedValue(s.depthBias);
    e.rasterSlopeScaledDepthBias = signedValue(s.slopeScaledDepthBias);
    e.rasterDepthBiasClamp = signedValue(s.depthBiasClamp);
    e.borderStored = conventionBorderDepth(settings.sampler.borderDepth, light.reversedZ);
    switch (s.format) {
        case DepthFormat::D16: e.depthBits = 16; e.floatDepth = false; break;
        case DepthFormat::D24: e.depthBits = 24; e.floatDepth = false; break;
        case DepthFormat::D32F: e.depthBits = 32; e.floatDepth = true; break;
    }
    // UNORM: r = 1 / (2^n - 1). Float: r = 2^(exponent(max depth of the primitive) - 23), 2^-24 for depths in [0.5, 1).
    e.depthStep = depthStepAt(s.format, 0.75);  // D32F: the step for depths in [0.5, 1)
    e.d3dDepthBias = int(std::lround(double(e.rasterDepthBias)));
    e.d3dDepthBiasError = double(e.d3dDepthBias) - double(e.rasterDepthBias);
    e.texelWorldSize = light.texelWorldSize;
    // As the main pass's LightData.depth.z: directional a texel's world size, perspective per unit of depth.
    e.texelWorldPerDepth = light.perspective ? 2.0 * light.tanHalfFov / double(std::max(light.resolution, 1)) : 0.0;
    e.normalOffsetWorld = double(s.normalOffset) * light.texelWorldSize;
    e.nearPlane = light.nearPlane;
    e.farPlane = light.farPlane;
    e.linearCompare = filterIsBilinear(settings.filter.kind);
    const FilterTechnique& technique = filterTechnique(settings.filter.kind);
    e.receiverPlane = s.receiverPlaneBias && technique.receiverPlane && light.cubeFace < 0;
    e.lightSpread = lightSpread(l);
    if (const MomentTechnique* m = technique.moments) {
        e.momentTechnique = true;
        e.techniqueUniforms = m->uniforms(settings.filter);
        e.momentFormat = momentImageFormat(technique, settings.filter.momentBits);
        e.momentBorder = m->encode(settings.sampler.borderDepth, e.techniqueUniforms);  // as MomentsPass's sampler
        if (m->clamps) e.techniqueClamps = m->clamps(settings.filter);
        // ShadowLab blurs a point light's cube as one surface, across its faces' edges
        // (shaders/moments_cube_blur.comp.glsl); the exported blur is the 2D one, face by face.
        if (l.type == LightType::Point && e.views.front().blurTexels > 1.0)
            e.notExported.push_back(
                "the blur across the cube faces' edges (ShadowLab blurs a point light's six faces as one surface, "
                "shaders/moments_cube_blur.comp.glsl; the blur below is face by face, so the faces disagree near "
                "their edges)");
    } else if (const OwnLookup* own = technique.ownLookup) {
        e.ownLookup = true;
        e.techniqueUniforms = own->uniforms(settings.filter);
    }
    return e;
}

std::optional<ShadowExportSet> exportForScene(const Settings& requested, const Scene& scene,
                                              const std::string& sceneLabel, std::optional<std::size_t> onlyLight,
                                              std::string& error, const ViewCamera* camera,
                                              const std::string& onlyView) {
    if (const std::vector<std::string> problems = requested.validate(); !problems.empty()) {
        error = problems.front();
        return std::nullopt;
    }
    const Settings settings = withEffectiveLights(requested, scene);
    ShadowExportSet set;
    set.sceneLabel = sceneLabel;
    set.lightSource = describeLightSource(requested, scene);
    set.lightCount = settings.lights.size();
    set.onlyLight = onlyLight;
    if (onlyLight && *onlyLight >= settings.lights.size()) {
        const std::string key = "lights." + std::to_string(*onlyLight);
        error = settings.lights.empty()
                    ? "--light " + std::to_string(*onlyLight) + ": there is no " + key + ": " + set.lightSource +
                          " (no light at all)"
                    : "--light " + std::to_string(*onlyLight) + ": there is no " + key + " (lights 0.." +
                          std::to_string(settings.lights.size() - 1) + ": " + set.lightSource + ")";
        return std::nullopt;
    }
    if (!onlyView.empty() && !onlyLight) {
        error = "--view " + onlyView + ": say which light with --light N (a view belongs to one light)";
        return std::nullopt;
    }
    // The renderer's origin (the scene's centre); the light's sizes do not depend on it.
    const glm::dvec3 origin = renderOriginOf(scene.bounds);
    for (std::size_t i = 0; i < settings.lights.size(); ++i) {
        if (onlyLight && i != *onlyLight) continue;
        const LightSettings& l = settings.lights[i];
        LightExport out;
        out.index = i;
        out.type = l.type;
        out.label = lightLabel(i, l.type);
        if (!l.enabled) {
            out.noShadowReason = "disabled (lights." + std::to_string(i) + ".enabled = false): neither shines nor casts";
        } else if (!l.castsShadows) {
            out.noShadowReason = "casts no shadow (lights." + std::to_string(i) +
                                 ".castsShadows = false): it shines everywhere, no shadow map";
        } else {
            auto views = buildLightViews(l, i, scene.bounds, origin, camera, error);
            if (!views) return std::nullopt;
            const bool cascaded = views->front().kind == ShadowViewKind::Cascade;
            const std::size_t viewCount = views->size();
            if (!onlyView.empty()) {  // --view: that view alone
                const std::optional<std::size_t> v = findView(*views, onlyView, error);
                if (!v) return std::nullopt;
                *views = {(*views)[*v]};
            }
            ShadowExport e = makeShadowExport(settings, i, views->front().space, sceneLabel);
            e.views.clear();
            for (const ShadowView& view : *views) {
                ExportView v = viewOf(i, l.type, view.space);
                v.normalOffsetWorld = double(l.shadow.normalOffset) * view.space.texelWorldSize;
                setBlur(v, settings.filter, view.space);
                if (cascaded) {
                    v.label = lightLabel(i, l.type) + " " + viewSuffix(view.kind, view.index);
                    v.cascade = view.index;
                    v.farDepth = view.slice.farDepth;
                    v.blendStart = view.slice.blendStart;
                    // Each cascade's own receivers and texel: the texel-relative terms differ per cascade.
                    v.bias = biasReport(l.shadow, l.shadow.format, view.space, receiverDepths(scene, view.space, origin));
                }
                e.views.push_back(std::move(v));
            }
            e.renderOrigin = origin;
            e.cascaded = cascaded;
            e.cascadeCount = cascaded ? viewCount : 0;
            if (cascaded) e.camera = views->front().slice.camera;
            // The depth-bias report needs one view's receivers; a point light's are spread over six faces, a cascaded
            // light's are per cascade (above).
            if (views->size() == 1 && !cascaded)
                e.bias = biasReport(l.shadow, l.shadow.format, views->front().space,
                                    receiverDepths(scene, views->front().space, origin));
            else if (cascaded)
                e.bias = e.views.front().bias;
            out.shadow = std::move(e);
        }
        set.lights.push_back(std::move(out));
    }
    return set;
}

}  // namespace shadowlab
