#pragma once
// The current light's shadow state as another API would need it: the rasterizer's depth bias, cull mode and depth
// clamp, the comparison sampler and filter, and the normal offset in world units. One table of numbers
// (ShadowExport), then a snippet per API (export_snippets.h). No GL here.
//
// Why the bias numbers carry over unchanged: every API applies DepthBias / polygon offset to the WINDOW depth, which
// is [0,1] in all of them. ShadowLab's GL pass uses the [-1,1] clip depth of glm::ortho / glm::perspective without
// glClipControl and glDepthRange(0,1), so window depth = clip z * 0.5 + 0.5. A D3D / Vulkan pass using the same
// matrix remapped to [0,1] clip depth (z' = 0.5 z + 0.5 w) produces the same window depth, hence the same depth
// slope, the same r and the same world-space bias. (tests/vulkan proves it on lavapipe.)
// Reversed-Z (shadow.reversedZ): the light matrix is already zero-to-one with near 1 and far 0, the pass clears to 0
// and tests GREATER, the sampler compares GREATER_OR_EQUAL with the border depth mirrored, and the rasterizer's bias
// values are the NEGATED settings (ShadowLab's DepthBias pushes away from the light, which is toward 0 there).
#include "light/depth_bias.h"
#include "light/light_space.h"
#include "settings/settings.h"

#include <optional>
#include <string>

namespace shadowlab {

enum class ExportFormat { D3D12, D3D11, Vulkan, GL, Json };

// "d3d12" -> D3D12 ...; nullopt for anything else.
std::optional<ExportFormat> parseExportFormat(const std::string& name);
// "d3d12|d3d11|vulkan|gl|json", for messages.
const char* exportFormatChoices();

struct ShadowExport {
    std::string sceneLabel;  // which scene the world-unit figures were computed for
    ShadowMapSettings shadow;
    SamplerSettings sampler;
    FilterSettings filter;
    bool depthClamp = true;
    bool perspective = false;
    bool reversedZ = false;

    // What the API's rasterizer and sampler take: the settings, negated for reversed-Z (biasSign -1), and the border
    // depth as stored (1 - sampler.borderDepth reversed).
    float biasSign = 1.0f;
    float rasterDepthBias = 0.0f, rasterSlopeScaledDepthBias = 0.0f, rasterDepthBiasClamp = 0.0f;
    float borderStored = 1.0f;

    int depthBits = 32;             // 16, 24, or 32 (float)
    bool floatDepth = true;
    double depthStep = 0.0;         // r: UNORM 1/(2^n - 1); D32F: 2^-24, the step at depths in [0.5, 1)
    int d3dDepthBias = 0;           // D3D11 / D3D12_RASTERIZER_DESC's INT DepthBias (rasterDepthBias rounded)
    double d3dDepthBiasError = 0.0; // (d3dDepthBias - rasterDepthBias), in units of r
    double texelWorldSize = 0.0;    // world size of one texel (spot: at the scene centre's distance)
    double normalOffsetWorld = 0.0; // the normal offset in world units (normalOffset texels x texelWorldSize)
    double nearPlane = 0.0, farPlane = 1.0;
    bool linearCompare = false;     // hardware 2x2 and Poisson use the comparison's bilinear filter
    BiasReport bias;                // the bias at the scene's receivers (valid when the scene was given)
};

// The numbers for `settings` with `light` (built for the scene named `sceneLabel`).
ShadowExport makeShadowExport(const Settings& settings, const LightSpace& light, const std::string& sceneLabel);

}  // namespace shadowlab

namespace shadowlab {

struct Scene;
// The light ShadowLab would use for `settings` on `scene` (its glTF light when light.useSceneLight, the auto-fit
// volume), then makeShadowExport. nullopt with `error` set when the settings or the light cannot be used.
std::optional<ShadowExport> exportForScene(const Settings& settings, const Scene& scene, const std::string& sceneLabel,
                                           std::string& error);

}  // namespace shadowlab
