#pragma once
// Every light's shadow state as another API would need it: the rasterizer's depth bias, cull mode and depth
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
#include "views/view_camera.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

struct FilterTechnique;

enum class ExportFormat { D3D12, D3D11, Vulkan, GL, Json };

// "d3d12" -> D3D12 ...; nullopt for anything else.
std::optional<ExportFormat> parseExportFormat(const std::string& name);
// "d3d12|d3d11|vulkan|gl|json", for messages.
const char* exportFormatChoices();

// One shadow view of a light: a directional or spot light has one, a point light six (cube faces, GL order), a
// cascaded directional light one per cascade (nearest the camera first).
struct ExportView {
    std::string label;           // "light 1 (spot)", "light 2 (point) face +X", "light 0 (directional) cascade:1"
    int cubeFace = -1;           // 0..5 for a point light's face, -1 otherwise
    int cascade = -1;            // a cascade's index (0 = nearest the camera), -1 otherwise
    double farDepth = 0.0;       // a cascade: it holds points up to this depth in front of the camera...
    double blendStart = 0.0;     // ...and from this depth on fades into the next (= farDepth: no band)
    double normalOffsetWorld = 0.0;  // the normal offset in this view's texels (a cascade's own), world units
    BiasReport bias;             // a cascade: the bias at the receivers in its volume (valid when there are some)
    glm::dmat4 viewProjection{1.0};  // render-origin-relative world -> ShadowLab's light clip space (column-major)
    double nearPlane = 0.0, farPlane = 1.0;
    double texelWorldSize = 0.0; // directional: constant; perspective: at the scene centre's distance
    double blurTexels = 1.0;     // a moments technique: the blur's width in this view's texels (filter.blurUnit)
    bool blurClamped = false;    // ...clamped to kMaxBlurTexels
};

// One light's shadow state (every view of a light shares it).
struct ShadowExport {
    std::string sceneLabel;  // which scene the world-unit figures were computed for
    std::size_t lightIndex = 0;
    LightType lightType = LightType::Directional;
    std::string label;       // "light 1 (spot)"
    std::vector<ExportView> views;  // the light's views: 1, 6 for a point light, one per cascade (or the --view one)
    bool cascaded = false;          // views are cascades, selected per pixel by its depth in front of `camera`
    ViewCamera camera;              // cascaded: the camera they were fitted to (render-origin-relative)
    std::size_t cascadeCount = 0;   // cascaded: the light's cascades (views may hold only the one asked for)
    glm::dvec3 renderOrigin{0.0};   // the matrices take world positions minus this
    glm::dvec3 lightPosition{0.0};  // spot / point: render-origin-relative
    glm::dvec3 lightDirection{0.0, -1.0, 0.0};  // directional / spot: unit, the direction light travels
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
    double texelWorldSize = 0.0;    // world size of one texel (spot / point: at the scene centre's distance)
    double texelWorldPerDepth = 0.0;  // perspective: a texel's world size per unit of distance along the view axis
    double normalOffsetWorld = 0.0; // the normal offset in world units (normalOffset texels x texelWorldSize)
    double nearPlane = 0.0, farPlane = 1.0;
    bool linearCompare = false;     // hardware 2x2 and Poisson use the comparison's bilinear filter
    // Receiver-plane depth bias is in effect: shadow.receiverPlaneBias on, a filter whose taps leave the centre (PCF,
    // Poisson) and a 2D view (not a point light), as ShadowLab's main pass applies it.
    bool receiverPlane = false;
    BiasReport bias;                // the bias at the scene's receivers (valid when the scene was given)

    // A technique whose lookup is GLSL of its own (filter_technique.h): a moments technique (its moments and blur
    // passes too) or one with its own lookup (PCSS). Its uTechnique as the renderer sets it (after the clamps), and the
    // light's size as lookups spread it (LightData.views.z).
    bool momentTechnique = false;
    bool ownLookup = false;
    glm::vec4 techniqueUniforms{0.0f};
    float lightSpread = 0.0f;
    // Moments: the storage's GLSL image format ("rg32f", "rgba16"...) and what the settings asked for that the storage
    // cannot hold (EVSM's exponents), each naming its key.
    std::string momentFormat;
    glm::vec4 momentBorder{0.0f};  // the moments sampler's border colour: the border depth's moments
    std::vector<std::string> techniqueClamps;
    // Settings of this light's technique the export does not write, each with what is written instead (the snippet
    // and the JSON say so: nothing is dropped silently).
    std::vector<std::string> notExported;
};

// A moments technique's storage as a GLSL image format ("rg16f", "rg32f", "rgba16f", "rgba32f", "rgba16": MSM's
// quantized 16 bits are unorm), what the moments pass allocates (shadow/moments_pass.h's momentInternalFormat; the
// Vulkan export test checks both agree). "" for a technique without moments.
std::string momentImageFormat(const FilterTechnique& technique, int momentBits);

// "light 1 (spot)"; with a cube face "light 2 (point) face +X".
std::string lightLabel(std::size_t index, LightType type);
std::string viewLabel(std::size_t index, LightType type, int cubeFace);

// The numbers for light `lightIndex` of `settings` whose first (or only) view is `light` (built for the scene named
// `sceneLabel`). The view list holds `light`; exportForScene adds a point light's other faces.
ShadowExport makeShadowExport(const Settings& settings, std::size_t lightIndex, const LightSpace& light,
                              const std::string& sceneLabel);

// A light of the effective set as exported: its shadow state, or why it has none.
struct LightExport {
    std::size_t index = 0;
    LightType type = LightType::Directional;
    std::string label;                  // "light 1 (spot)"
    std::optional<ShadowExport> shadow; // set when the light is enabled and casts shadows
    std::string noShadowReason;         // otherwise: "disabled (neither shines nor casts)" / "castsShadows off ..."
};

// What `shadowlab export` writes: every light of the effective set (or the one asked for).
struct ShadowExportSet {
    std::string sceneLabel;
    std::string lightSource;        // describeLightSource: whose lights these are
    std::size_t lightCount = 0;     // lights in the effective set
    std::optional<std::size_t> onlyLight;  // --light N
    std::vector<LightExport> lights;
};

}  // namespace shadowlab

namespace shadowlab {

struct Scene;
// Every light ShadowLab would use for `settings` on `scene` (withEffectiveLights: its glTF lights when
// useSceneLights, the auto-fit volumes), each with every view. `onlyLight`: that light alone; a light that does not
// exist is an error naming lights.N and the valid range. nullopt with `error` set when the settings or a light cannot
// be used. A set with no light is not an error: the snippet says that nothing casts.
// `camera`: the view's camera, render-origin-relative (cascades follow it; without one a cascaded light is an error
// saying so). `onlyView`: with onlyLight, that view of it alone ("+X", "cascade:2"; views/shadow_view.h's findView).
std::optional<ShadowExportSet> exportForScene(const Settings& settings, const Scene& scene, const std::string& sceneLabel,
                                              std::optional<std::size_t> onlyLight, std::string& error,
                                              const ViewCamera* camera = nullptr, const std::string& onlyView = "");

}  // namespace shadowlab
