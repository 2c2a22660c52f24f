#pragma once
// The shader half of an export: the terms of the shadow factor S that are shader techniques, not pipeline state —
// normal offset, receiver-plane depth bias, the filter's tap loop (PCF grid / Poisson disk, offsets from
// shading/filter_taps.h, the renderer's own table) and keeping a lookup's taps inside the map. Written once, here,
// and printed in GLSL (GL, Vulkan) or HLSL (D3D11, D3D12): the same lines, only the language's words differ. It
// mirrors the main pass (shaders/shadow/lookup_2d.glsl, compare_2d.glsl, lookup_cube.glsl, main.frag.glsl's offsetLookup);
// tests/unit/test_shadow_export.cpp checks the constants both use.
#include "export/glsl_uniforms.h"
#include "export/shadow_export.h"

#include <string>

namespace shadowlab {

enum class ShaderLanguage { Glsl, Hlsl };

// How the exported map is addressed, per API: GL and Vulkan store row 0 at clip y = -1 (v = 0.5 + 0.5 y_ndc), D3D at
// clip y = +1 (v = 0.5 - 0.5 y_ndc, tap offsets' y mirrored). Depth: GL without reversed-Z is ShadowLab's [-1,1]
// clip depth (window = 0.5 z + 0.5); every other case a zero-to-one matrix (window = z_ndc).
struct ShaderTarget {
    ShaderLanguage language = ShaderLanguage::Glsl;
    bool flipV = false;             // D3D
    bool zeroToOneDepth = false;    // the matrix the shader gets has clip depth [0,1]
    bool vulkan = false;            // Vulkan GLSL: descriptors need bindings (no loose uniforms)
};
ShaderTarget shaderTargetFor(ExportFormat format, bool reversedZ);

// The receiver-plane constants shaders/shadow/compare_2d.glsl holds (kReceiverPlaneMaxSlope, the singular-Jacobian threshold).
inline constexpr double kExportReceiverPlaneMaxSlope = 8.0;
inline constexpr double kExportReceiverPlaneSingular = 1e-3;

// The shortest decimal that reads back as the same float, always with a '.' or an exponent ("0.5", "2.0",
// "1e-30"): the one float text of every snippet (C++ literals add "f").
std::string shortestFloatText(float value);

// The shader functions computing S for one light (`lightN...` names), with a comment saying what they take. A
// technique whose lookup is GLSL of its own (moments techniques, PCSS) gets techniqueLookupCode (HLSL: that GLSL as
// comments, to translate).
std::string shadowShaderCode(const ShadowExport& light, const ShaderTarget& target);

// A technique whose lookup is GLSL of its own: the renderer's shaders/shadow/lookup.glsl as the main pass compiles it
// for this technique and light kind (the variant's defines, every #include expanded: light_data.glsl, the technique's
// file...), its uTechnique (and PCSS's unused uFilterScale) baked in with the exported values, for Vulkan every map
// sampler given a descriptor binding (`bindings`); then `lightN...` functions that fill the LightData those files read
// from the exported numbers and apply the normal offset as the main pass does. GLSL only.
std::string techniqueLookupCode(const ShadowExport& light, bool vulkan, std::vector<VulkanBinding>* bindings = nullptr);

// A moments technique's compute passes: shaders/moments.comp.glsl as the moments pass compiles it, CONVERT (the
// depth map to the technique's moments, its file included), the blur (one direction per dispatch), uTechnique
// baked in, and with filter.momentMips MIPS (one level from the one below per dispatch, uSize the level's size; else
// empty); for Vulkan with every uniform given a binding (listed in the bindings).
struct MomentsPassShaders {
    std::string convert, blur, mips;
    std::vector<VulkanBinding> convertBindings, blurBindings, mipsBindings;
};
MomentsPassShaders momentsPassShaders(const ShadowExport& light, bool vulkan);

}  // namespace shadowlab
