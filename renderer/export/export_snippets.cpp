#include "export/export_snippets.h"

#include "export/glsl_uniforms.h"
#include "export/shadow_shader_code.h"
#include "settings/settings_fields.h"
#include "shading/filter_taps.h"
#include "shading/filters/filter_technique.h"
#include "shading/filters/moment_filter.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <sstream>

namespace shadowlab {

namespace {

// A C++ float literal that reads back as the same float ("2.0f", "0.0078125f").
std::string floatLiteral(float value) { return shortestFloatText(value) + "f"; }

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

const char* formatName(const ShadowExport& e, ExportFormat api) {
    switch (api) {
        case ExportFormat::D3D12:
        case ExportFormat::D3D11:
            return e.depthBits == 16 ? "DXGI_FORMAT_D16_UNORM (SRV DXGI_FORMAT_R16_UNORM)"
                   : e.depthBits == 24 ? "DXGI_FORMAT_D24_UNORM_S8_UINT (SRV DXGI_FORMAT_R24_UNORM_X8_TYPELESS)"
                                       : "DXGI_FORMAT_D32_FLOAT (SRV DXGI_FORMAT_R32_FLOAT)";
        case ExportFormat::Vulkan:
            return e.depthBits == 16 ? "VK_FORMAT_D16_UNORM"
                   : e.depthBits == 24 ? "VK_FORMAT_X8_D24_UNORM_PACK32"
                                       : "VK_FORMAT_D32_SFLOAT";
        case ExportFormat::GL:
        case ExportFormat::Json:
            return e.depthBits == 16 ? "GL_DEPTH_COMPONENT16"
                   : e.depthBits == 24 ? "GL_DEPTH_COMPONENT24"
                                       : "GL_DEPTH_COMPONENT32F";
    }
    return "?";
}

// The comment block every snippet starts with: what the numbers mean and which conventions they assume.
std::string conventions(const ShadowExport& e, ExportFormat api, const char* c) {
    const ShadowMapSettings& s = e.shadow;
    std::ostringstream o;
    const bool cube = e.lightType == LightType::Point;
    o << c << e.label << (cube ? " (six cube-face views)" : e.cascaded ? " (cascaded: " + std::to_string(e.cascadeCount) +
                                                                          " cascades following the camera)" : "")
      << ": ShadowLab shadow pass, exported for " << (api == ExportFormat::D3D12 ? "Direct3D 12"
                                                           : api == ExportFormat::D3D11 ? "Direct3D 11"
                                                           : api == ExportFormat::Vulkan ? "Vulkan" : "OpenGL 4.5")
      << "\n";
    o << c << "Shadow map: " << (cube ? "a cube map of six " : e.cascaded ? "a 2D array of one layer per cascade, each " : "")
      << s.resolution << "x" << s.resolution
      << (cube ? " faces" : "") << ", " << formatName(e, api)
      << (e.reversedZ ? "; depth test GREATER, cleared to 0.0: REVERSED-Z (near 1, far 0).\n"
                      : "; depth test LESS, cleared to 1.0: NOT reversed-Z.\n");
    if (e.reversedZ)
        o << c << "Depth range: ShadowLab's reversed-Z light matrix is zero-to-one with near and far swapped (near -> 1,\n"
          << c << "  far -> 0)" << (api == ExportFormat::GL ? ", drawn under glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)" : "")
          << ": window depth = z_ndc. Use it as is.\n"
          << c << "Bias sign: ShadowLab's DepthBias " << number(s.depthBias) << ", SlopeScaledDepthBias "
          << number(s.slopeScaledDepthBias) << " and DepthBiasClamp " << number(s.depthBiasClamp)
          << " push away from the light,\n"
          << c << "  which is toward 0 here: the rasterizer values below are NEGATED (the same bias in depth steps).\n";
    else if (api == ExportFormat::GL)
        o << c << "Depth range: ShadowLab's light matrix has GL clip depth [-1,1] (no glClipControl), glDepthRange(0,1):\n"
          << c << "  window depth = 0.5 * z_ndc + 0.5 in [0,1]. Polygon offset acts on window depth, so with\n"
          << c << "  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) and a [0,1] matrix the same numbers give the same bias.\n";
    else
        o << c << "Depth range: clip depth [0,1]. Use ShadowLab's light matrix remapped from GL's [-1,1]\n"
          << c << "  (z' = 0.5 z + 0.5 w): window depth is then identical to ShadowLab's, and so are the depth slope,\n"
          << c << "  r and the world-space bias; the values below need no conversion.\n";
    if (e.floatDepth)
        o << c << "r (minimum resolvable difference), 32-bit float depth: r = 2^(exponent(max depth of the primitive) - 23),\n"
          << c << "  i.e. the constant bias scales with the primitive's largest depth (2^-24 = " << number(e.depthStep)
          << " for depths in [0.5,1)).\n";
    else
        o << c << "r (minimum resolvable difference), " << e.depthBits << "-bit UNORM: r = 1/(2^" << e.depthBits
          << " - 1) = " << number(e.depthStep) << "\n";
    o << c << "Bias = DepthBias * r + SlopeScaledDepthBias * MaxDepthSlope, then clamped to DepthBiasClamp"
      << (s.depthBiasClamp == 0.0f ? " (0 = no clamp)" : "") << ".\n";
    if (e.cascaded)
        o << c << "Cascades: the same rasterizer bias in every cascade; what it amounts to in each (its receivers, its\n"
          << c << "  texel) is listed with each cascade's view below, and the normal offset scales with each cascade's texel.\n";
    else if (e.bias.valid)
        o << c << "At " << e.sceneLabel << "'s receivers (window depth " << number(e.bias.receiverDepthMin) << ".."
          << number(e.bias.receiverDepthMax) << "): DepthBias = " << number(e.bias.constantNear.world) << ".."
          << number(e.bias.constantFar.world) << " world units,\n" << c << "  slope-scaled at the median slope = "
          << number(e.bias.slope.world) << ", total at the median receiver = " << number(e.bias.total.world)
          << " world units (" << number(e.bias.total.texels) << " texels).\n";
    o << c << "Winding: counter-clockwise triangles (glTF) are front faces.\n";
    o << c << "Depth clamp: " << (e.depthClamp ? "on (casters in front of the near plane still cast)" : "off")
      << (!e.depthClamp && e.lightType != LightType::Directional ? " (ShadowLab clamps directional views only)" : "")
      << ".\n";
    o << c << "Normal offset (in the receiver's shader, not the rasterizer): move the lookup position along the surface\n"
      << c << "  normal by " << number(s.normalOffset) << " texels = " << number(e.normalOffsetWorld)
      << " world units (one texel = " << number(e.texelWorldSize) << " world units for scene " << e.sceneLabel
      << (cube ? ", at the scene centre's distance: scale it with the distance along the face's axis"
          : e.perspective ? ", at the scene centre's distance: scale it with the distance along the spot's axis" : "")
      << ").\n";
    o << c << "Light volume (as fitted for that scene): near " << number(e.nearPlane) << ", far " << number(e.farPlane)
      << (cube ? " (six 90-degree perspective cube faces)" : e.perspective ? " (perspective spot)" : " (orthographic, directional)")
      << ".\n";
    const FilterSettings& f = e.filter;
    o << c << "Filter: ";
    switch (f.kind) {
        case FilterKind::Point: o << "one point comparison"; break;
        case FilterKind::Hardware2x2: o << "one bilinear (2x2) comparison"; break;
        case FilterKind::Pcf: o << f.kernel << "x" << f.kernel << " grid of point comparisons at texel centres, averaged"; break;
        case FilterKind::Poisson:
            o << kPoissonTaps << " Poisson-disk bilinear comparisons within " << number(f.poissonRadius) << " texels, averaged";
            break;
        case FilterKind::Pcss:
            o << "PCSS: a " << kPoissonTaps << "-tap blocker search (at most " << number(f.blockerSearchTexels)
              << " texels), then " << kPoissonTaps << " bilinear comparisons as wide as the penumbra (at most "
              << number(f.penumbraMaxTexels) << " texels) from the light's size (" << number(e.lightSpread)
              << " as the lookup spreads it)";
            break;
        default:  // a moments technique: its lookup reads the moments, not the comparison sampler
            o << filterTechnique(f.kind).name << ": one bilinear read of the blurred moments (" << e.momentFormat
              << "; the moments pass below), uTechnique = (" << number(e.techniqueUniforms.x) << ", "
              << number(e.techniqueUniforms.y) << ", " << number(e.techniqueUniforms.z) << ", "
              << number(e.techniqueUniforms.w) << ")";
            break;
    }
    o << (e.reversedZ ? "; compare: lit when receiver depth >= stored depth (GEQUAL).\n"
                      : "; compare: lit when receiver depth <= stored depth (LEQUAL).\n");
    o << c << "Receiver-plane depth bias: "
      << (e.receiverPlane ? "ON: every tap compares the receiver plane's depth at the tap (shader code below)"
          : !s.receiverPlaneBias ? "off"
          : cube ? "set, but not applied to cube faces (as in ShadowLab)"
                 : "set, but not applied: the filter takes a single centred tap (as in ShadowLab)")
      << ".\n";
    o << c << "Taps inside the map: a lookup inside the map clamps its taps to half a texel from the edge (shader code below).\n";
    if (cube)
        o << c << "Sampler: a cube map is sampled by direction: the address mode and border depth do not apply.\n";
    if (e.reversedZ && e.sampler.addressMode == AddressMode::ClampToBorder && !cube)
        o << c << "Border depth: ShadowLab's sampler.borderDepth " << number(e.sampler.borderDepth) << " (1 = lit outside) is stored as "
          << number(e.borderStored) << " in reversed-Z.\n";
    return o.str();
}

const char* d3dCull(const ShadowExport& e, bool d3d12) {
    switch (e.shadow.cullMode) {
        case CullMode::Back: return d3d12 ? "D3D12_CULL_MODE_BACK" : "D3D11_CULL_BACK";
        case CullMode::Front: return d3d12 ? "D3D12_CULL_MODE_FRONT" : "D3D11_CULL_FRONT";
        case CullMode::None: return d3d12 ? "D3D12_CULL_MODE_NONE" : "D3D11_CULL_NONE";
    }
    return "?";
}

const char* addressName(AddressMode mode, ExportFormat api) {
    const bool d3d12 = api == ExportFormat::D3D12;
    switch (mode) {
        case AddressMode::Wrap:
            return api == ExportFormat::Vulkan ? "VK_SAMPLER_ADDRESS_MODE_REPEAT"
                   : api == ExportFormat::GL   ? "GL_REPEAT"
                   : d3d12                     ? "D3D12_TEXTURE_ADDRESS_MODE_WRAP" : "D3D11_TEXTURE_ADDRESS_WRAP";
        case AddressMode::ClampToEdge:
            return api == ExportFormat::Vulkan ? "VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE"
                   : api == ExportFormat::GL   ? "GL_CLAMP_TO_EDGE"
                   : d3d12                     ? "D3D12_TEXTURE_ADDRESS_MODE_CLAMP" : "D3D11_TEXTURE_ADDRESS_CLAMP";
        case AddressMode::ClampToBorder:
            return api == ExportFormat::Vulkan ? "VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER"
                   : api == ExportFormat::GL   ? "GL_CLAMP_TO_BORDER"
                   : d3d12                     ? "D3D12_TEXTURE_ADDRESS_MODE_BORDER" : "D3D11_TEXTURE_ADDRESS_BORDER";
    }
    return "?";
}

// The matrix an API's pass takes for a view: ShadowLab's own (GL); for D3D and Vulkan its clip depth remapped to
// [0,1] (z' = 0.5 z + 0.5 w; a reversed-Z matrix is zero-to-one already); for a D3D cube face its clip y negated, so
// D3D (row 0 = clip y +1) stores the face's texels where a cube map's direction lookup reads them.
glm::dmat4 apiMatrix(const ShadowExport& e, const ExportView& v, ExportFormat api) {
    glm::dmat4 m = v.viewProjection;
    const bool d3d = api == ExportFormat::D3D12 || api == ExportFormat::D3D11;
    if (api != ExportFormat::GL && !e.reversedZ)
        for (int c = 0; c < 4; ++c) m[c][2] = 0.5 * m[c][2] + 0.5 * m[c][3];
    if (d3d && v.cubeFace >= 0)
        for (int c = 0; c < 4; ++c) m[c][1] = -m[c][1];
    return m;
}

std::string matrixName(const ShadowExport& e, const ExportView& v) {
    static const char* faces[6] = {"PX", "NX", "PY", "NY", "PZ", "NZ"};
    std::string name = "light" + std::to_string(e.lightIndex);
    if (v.cubeFace >= 0 && v.cubeFace < 6) name += std::string("Face") + faces[v.cubeFace];
    if (v.cascade >= 0) name += "Cascade" + std::to_string(v.cascade);
    return name + "ViewProjection";
}

// Every view of the light: which one it is, its near / far and its matrix, as C++ the host code can paste.
std::string viewsBlock(const ShadowExport& e, ExportFormat api) {
    const bool d3d = api == ExportFormat::D3D12 || api == ExportFormat::D3D11;
    std::ostringstream o;
    o << "\n// " << e.label << ": " << e.views.size()
      << (e.cascaded ? (e.views.size() == e.cascadeCount
                            ? " views (cascades, nearest the camera first; layer = cascade)"
                            : " view of its " + std::to_string(e.cascadeCount) + " cascades (--view)")
          : e.views.size() == 1 ? " view" : " views (cube faces, layer = face in the order +X,-X,+Y,-Y,+Z,-Z)")
      << ". Matrices: column-major, taking world positions minus the render origin ("
      << number(e.renderOrigin.x) << ", " << number(e.renderOrigin.y) << ", " << number(e.renderOrigin.z) << ");\n// "
      << (api == ExportFormat::GL ? (e.reversedZ ? "ShadowLab's zero-to-one reversed-Z matrix (near 1, far 0)" : "ShadowLab's own ([-1,1] clip depth)")
          : e.reversedZ ? "ShadowLab's zero-to-one reversed-Z matrix (near 1, far 0), as is"
                        : "ShadowLab's matrix with its clip depth remapped to [0,1] (z' = 0.5 z + 0.5 w)")
      << (d3d && e.lightType == LightType::Point ? "; cube faces with clip y negated (D3D's row 0 is clip y +1)" : "")
      << (d3d ? "; HLSL: column_major float4x4, mul(M, v)" : "; GLSL mat4") << ".\n";
    for (const ExportView& v : e.views) {
        const glm::dmat4 m = apiMatrix(e, v, api);
        o << "// View " << v.label << ": near " << number(v.nearPlane) << ", far " << number(v.farPlane)
          << ", one texel = " << number(v.texelWorldSize) << " world units" << (e.perspective ? " at the scene centre's distance" : "");
        if (v.cascade >= 0) {
            o << ".\n//   Holds points up to depth " << number(v.farDepth) << " in front of the camera";
            if (v.blendStart < v.farDepth) o << ", fading into cascade:" << v.cascade + 1 << " from " << number(v.blendStart);
            o << "; normal offset " << number(e.shadow.normalOffset) << " texels = " << number(v.normalOffsetWorld)
              << " world units";
            if (v.bias.valid)
                o << ";\n//   at its receivers: DepthBias = " << number(v.bias.constantNear.depth) << " depth = "
                  << number(v.bias.constantNear.world) << " world units = " << number(v.bias.constantNear.texels)
                  << " texels, total at the median receiver = " << number(v.bias.total.depth) << " depth = "
                  << number(v.bias.total.world) << " world units = " << number(v.bias.total.texels) << " texels";
            else
                o << " (no receiver in its volume)";
        }
        o << ".\nstatic const float " << matrixName(e, v) << "[16] = {";
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) o << (c || r ? ", " : "") << floatLiteral(float(m[c][r]));
        o << "};\n";
    }
    return o.str();
}

// A moments storage format's name in each API.
std::string momentFormatName(const std::string& glsl, ExportFormat api) {
    struct Names { const char *glsl, *gl, *vulkan, *dxgi; };
    static const Names names[] = {
        {"rg16f", "GL_RG16F", "VK_FORMAT_R16G16_SFLOAT", "DXGI_FORMAT_R16G16_FLOAT"},
        {"rg32f", "GL_RG32F", "VK_FORMAT_R32G32_SFLOAT", "DXGI_FORMAT_R32G32_FLOAT"},
        {"rgba16f", "GL_RGBA16F", "VK_FORMAT_R16G16B16A16_SFLOAT", "DXGI_FORMAT_R16G16B16A16_FLOAT"},
        {"rgba32f", "GL_RGBA32F", "VK_FORMAT_R32G32B32A32_SFLOAT", "DXGI_FORMAT_R32G32B32A32_FLOAT"},
        {"rgba16", "GL_RGBA16", "VK_FORMAT_R16G16B16A16_UNORM", "DXGI_FORMAT_R16G16B16A16_UNORM"}};
    for (const Names& n : names)
        if (glsl == n.glsl)
            return api == ExportFormat::Vulkan ? n.vulkan
                   : api == ExportFormat::D3D12 || api == ExportFormat::D3D11 ? n.dxgi : n.gl;
    return glsl;
}

// The bindings of `names` (the text keeps the branches the pass's defines leave out: the other passes' uniforms, uIn
// declared alike in two of them, listed once).
std::string bindingList(const std::vector<VulkanBinding>& bindings, std::initializer_list<const char*> names) {
    std::string out;
    for (const VulkanBinding& b : bindings)
        for (const char* name : names) {
            const std::string entry = "binding " + std::to_string(b.binding) + " = " + b.declaration;
            if (b.name == name && out.find(entry) == std::string::npos) out += (out.empty() ? "" : "; ") + entry;
        }
    return out;
}

// A moments technique's passes after the shadow pass: storage, sampler, each view's blur, and the two compute shaders
// (ShadowLab's shaders/moments.comp.glsl as its moments pass compiles them) as C++ raw strings to compile.
std::string momentsBlock(const ShadowExport& e, ExportFormat api) {
    const bool vulkan = api == ExportFormat::Vulkan;
    const MomentsPassShaders shaders = momentsPassShaders(e, vulkan);
    const std::string p = "light" + std::to_string(e.lightIndex);
    const glm::vec4& b = e.momentBorder;
    const bool mips = e.filter.momentMips;
    const int levels = momentLevels(e.shadow.resolution, mips);
    std::ostringstream o;
    o << "\n// ---- Moments pass (filter.kind " << filterTechnique(e.filter.kind).name
      << "): " << (mips ? "three" : "two") << " compute passes after the shadow pass, per view ----\n"
      << "// Storage: a moments image beside the depth map, the same size and layers, " << momentFormatName(e.momentFormat, api)
      << " (filter.momentBits " << e.filter.momentBits << ")"
      << (mips ? ", " + std::to_string(levels) + " mip levels (filter.momentMips)" : std::string())
      << ". The lookup samples it with "
      << (!mips ? "LINEAR min/mag"
          : vulkan ? "LINEAR min/mag, mipmapMode LINEAR, maxLod " + std::to_string(levels - 1)
                   : "LINEAR_MIPMAP_LINEAR min, LINEAR mag")
      << " filtering, no\n// comparison, address mode " << addressName(e.sampler.addressMode, api) << ", border colour = the border depth's moments ("
      << shortestFloatText(b.x) << ", " << shortestFloatText(b.y) << ", " << shortestFloatText(b.z) << ", " << shortestFloatText(b.w)
      << "). The comparison sampler above is not read by this lookup.\n";
    for (const std::string& clamp : e.techniqueClamps) o << "// Clamped: " << clamp << ".\n";
    for (const std::string& left : e.notExported) o << "// Not exported: " << left << ".\n";
    o << "// 1. Convert (" << p << "MomentsConvert): uDepth = the depth map as a plain 2D array (a cube map's faces as its\n"
      << "//    layers), uLayer = the view's layer, uOut = the moments image's layer (rgba image binding 0); dispatch\n"
      << "//    ceil(" << e.shadow.resolution << " / 8) x ceil(" << e.shadow.resolution << " / 8) groups.\n";
    if (mips)
        o << "// 2. Mips (" << p << "MomentsMips), before the blur (from the unblurred moments): for each level l = 1.."
          << levels - 1 << ": uIn (binding 1) = level l - 1 of the view's layer,\n//    uOut (binding 0) = level l, uSize = max("
          << e.shadow.resolution << " >> l, 1); dispatch ceil(uSize / 8) x ceil(uSize / 8) groups; barrier. Each texel is\n"
          << "//    the mean of the 2x2 below it that hold a caster (glGenerateMipmap would average in the cleared texels).\n";
    o << "// " << (mips ? "3" : "2") << ". Blur (" << p << "MomentsBlur"
      << (mips ? ", level 0 only" : "") << "), a view whose width is above 1 texel: uIn (binding 1) = its moments layer, uOut\n"
      << "//    (binding 0) = a scratch image of the same format and size, uDirection = (1, 0); barrier; then uIn = the scratch,\n"
      << "//    uOut = the layer, uDirection = (0, 1); barrier. uRadius = R and uWeights[0..R] per view ("
      << (e.filter.blurUnit == BlurUnit::World ? "filter.blurWidth " + number(e.filter.blurWidth) + " world units in each view's texels"
                                               : "filter.blurWidth " + number(e.filter.blurWidth) + " texels")
      << "):\n";
    for (const ExportView& v : e.views) {
        const std::vector<float> weights = blurWeights(v.blurTexels);
        const std::size_t r = weights.size() / 2;
        o << "//    " << v.label << ": " << number(v.blurTexels) << " texels" << (v.blurClamped ? " (clamped)" : "")
          << (r == 0 ? ": no blur\n" : ", uRadius " + std::to_string(r) + ", uWeights = {");
        for (std::size_t i = r; r > 0 && i < weights.size(); ++i) o << (i > r ? ", " : "") << shortestFloatText(weights[i]);
        if (r > 0) o << "}\n";
    }
    if (vulkan) {
        o << "// Vulkan descriptors (set 0). Convert: " << bindingList(shaders.convertBindings, {"uOut", "uDepth", "uLayer"})
          << ".\n// Blur: " << bindingList(shaders.blurBindings, {"uOut", "uIn", "uDirection", "uRadius", "uWeights"});
        if (mips) o << ".\n// Mips: " << bindingList(shaders.mipsBindings, {"uOut", "uIn", "uSize"});
        o << ". A std140 block holds its one value at offset 0 (uWeights: a 16-byte\n"
          << "// stride per float, uDirection an ivec2).\n";
    }
    if (api == ExportFormat::D3D12 || api == ExportFormat::D3D11)
        o << "// GLSL compute shaders (ShadowLab's): translate to HLSL (imageLoad / imageStore -> RWTexture2D reads / writes).\n";
    o << "static const char* " << p << "MomentsConvert = R\"glsl(\n" << shaders.convert << ")glsl\";\n"
      << "static const char* " << p << "MomentsBlur = R\"glsl(\n" << shaders.blur << ")glsl\";\n";
    if (mips) o << "static const char* " << p << "MomentsMips = R\"glsl(\n" << shaders.mips << ")glsl\";\n";
    return o.str();
}

std::string shaderBlock(const ShadowExport& e, ExportFormat api) {
    const ShaderTarget target = shaderTargetFor(api, e.reversedZ);
    const bool own = e.momentTechnique || e.ownLookup;
    return (e.momentTechnique ? momentsBlock(e, api) : std::string()) + "\n// ---- Shader code (" +
           std::string(target.language == ShaderLanguage::Hlsl && !own ? "HLSL" : "GLSL") + "): normal offset, " +
           (e.receiverPlane ? "receiver-plane depth bias, " : "") +
           (own ? std::string("ShadowLab's lookup for filter.kind ") + filterTechnique(e.filter.kind).name + " ----\n"
                : std::string("the filter's taps, taps kept inside the map ----\n")) +
           shadowShaderCode(e, target);
}

std::string d3d(const ShadowExport& e, ExportFormat api) {
    const bool d3d12 = api == ExportFormat::D3D12;
    const std::string p = d3d12 ? "D3D12_" : "D3D11_";
    std::ostringstream o;
    o << conventions(e, api, "// ");
    if (e.d3dDepthBiasError != 0.0)
        o << "// DepthBias is an INT here: " << number(e.rasterDepthBias) << " rounds to " << e.d3dDepthBias << " (off by "
          << number(e.d3dDepthBiasError) << " r)."
          << (d3d12 ? " D3D12_RASTERIZER_DESC1/DESC2 (Agility SDK pipeline state streams) take FLOAT DepthBias = " + floatLiteral(e.rasterDepthBias) +
                          " exactly."
                    : std::string(" Use a format with a finer r, or scale SlopeScaledDepthBias instead."))
          << "\n";
    o << p << "RASTERIZER_DESC shadowRaster = {};\n"
      << "shadowRaster.FillMode = " << p << (d3d12 ? "FILL_MODE_SOLID" : "FILL_SOLID") << ";\n"
      << "shadowRaster.CullMode = " << d3dCull(e, d3d12) << ";\n"
      << (e.lightType == LightType::Point
              ? "shadowRaster.FrontCounterClockwise = FALSE;  // cube faces: clip y negated (below) mirrors the winding\n"
              : "shadowRaster.FrontCounterClockwise = TRUE;\n")
      << "shadowRaster.DepthBias = " << e.d3dDepthBias << ";\n"
      << "shadowRaster.DepthBiasClamp = " << floatLiteral(e.rasterDepthBiasClamp) << ";\n"
      << "shadowRaster.SlopeScaledDepthBias = " << floatLiteral(e.rasterSlopeScaledDepthBias) << ";\n"
      << "shadowRaster.DepthClipEnable = " << (e.depthClamp ? "FALSE" : "TRUE") << ";  // FALSE = depth clamp\n"
      << (d3d12 ? "" : "shadowRaster.ScissorEnable = FALSE;\n") << "shadowRaster.MultisampleEnable = FALSE;\n"
      << "shadowRaster.AntialiasedLineEnable = FALSE;\n\n";
    const char* filter = e.linearCompare ? "FILTER_COMPARISON_MIN_MAG_LINEAR_MIP_POINT" : "FILTER_COMPARISON_MIN_MAG_MIP_POINT";
    const char* address = addressName(e.sampler.addressMode, api);
    const std::string border = floatLiteral(e.borderStored);
    o << p << "SAMPLER_DESC shadowSampler = {};\n"
      << "shadowSampler.Filter = " << p << filter << ";\n"
      << "shadowSampler.AddressU = " << address << ";\n"
      << "shadowSampler.AddressV = " << address << ";\n"
      << "shadowSampler.AddressW = " << address << ";\n"
      << "shadowSampler.ComparisonFunc = " << p
      << (e.reversedZ ? (d3d12 ? "COMPARISON_FUNC_GREATER_EQUAL" : "COMPARISON_GREATER_EQUAL")
                      : (d3d12 ? "COMPARISON_FUNC_LESS_EQUAL" : "COMPARISON_LESS_EQUAL"))
      << ";  // depth state: " << (e.reversedZ ? "GREATER, clear 0.0" : "LESS, clear 1.0") << "\n"
      << "shadowSampler.BorderColor[0] = shadowSampler.BorderColor[1] = shadowSampler.BorderColor[2] = "
         "shadowSampler.BorderColor[3] = " << border << ";\n"
      << "shadowSampler.MinLOD = 0.0f;\nshadowSampler.MaxLOD = 0.0f;\nshadowSampler.MaxAnisotropy = 1;\n";
    if (e.lightType == LightType::Point)
        o << "// Texture: a Texture2D resource with " << (d3d12 ? "DepthOrArraySize" : "ArraySize") << " = 6"
          << (d3d12 ? "" : " and D3D11_RESOURCE_MISC_TEXTURECUBE") << " (one DSV per face: a Texture2DArray slice),\n"
          << "// read through a TextureCube SRV.\n";
    o << viewsBlock(e, api) << shaderBlock(e, api);
    return o.str();
}

std::string vulkan(const ShadowExport& e) {
    const ShadowMapSettings& s = e.shadow;
    const bool bias = s.depthBias != 0.0f || s.slopeScaledDepthBias != 0.0f;
    std::ostringstream o;
    o << conventions(e, ExportFormat::Vulkan, "// ");
    o << "// Winding: with a positive-height viewport Vulkan's framebuffer y runs the other way from GL's window y, so\n"
         "// ShadowLab's counter-clockwise front faces wind clockwise: frontFace = VK_FRONT_FACE_CLOCKWISE, and image row 0\n"
         "// is clip y = -1, the same texel order as ShadowLab's GL map. (Negative-height viewport: COUNTER_CLOCKWISE.)\n";
    if (!e.floatDepth)
        o << "// Core Vulkan leaves a UNORM format's r to the implementation (some scale it up to 2x to guarantee a\n"
             "// resolvable offset); lavapipe uses 1/(2^n - 1) as above. To pin it, chain VkDepthBiasRepresentationInfoEXT\n"
             "// (VK_EXT_depth_bias_control): LEAST_REPRESENTABLE_VALUE_FORMAT_EXT with depthBiasExact = VK_TRUE.\n";
    if (e.depthClamp) o << "// depthClampEnable needs VkPhysicalDeviceFeatures::depthClamp.\n";
    if (s.depthBiasClamp != 0.0f) o << "// A non-zero depthBiasClamp needs VkPhysicalDeviceFeatures::depthBiasClamp.\n";
    const char* cull = s.cullMode == CullMode::Back    ? "VK_CULL_MODE_BACK_BIT"
                       : s.cullMode == CullMode::Front ? "VK_CULL_MODE_FRONT_BIT"
                                                       : "VK_CULL_MODE_NONE";
    o << "VkPipelineRasterizationStateCreateInfo shadowRaster = {VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};\n"
      << "shadowRaster.depthClampEnable = " << (e.depthClamp ? "VK_TRUE" : "VK_FALSE") << ";\n"
      << "shadowRaster.rasterizerDiscardEnable = VK_FALSE;\n"
      << "shadowRaster.polygonMode = VK_POLYGON_MODE_FILL;\n"
      << "shadowRaster.cullMode = " << cull << ";\n"
      << "shadowRaster.frontFace = VK_FRONT_FACE_CLOCKWISE;\n"
      << "shadowRaster.depthBiasEnable = " << (bias ? "VK_TRUE" : "VK_FALSE") << ";\n"
      << "shadowRaster.depthBiasConstantFactor = " << floatLiteral(e.rasterDepthBias) << ";\n"
      << "shadowRaster.depthBiasClamp = " << floatLiteral(e.rasterDepthBiasClamp) << ";\n"
      << "shadowRaster.depthBiasSlopeFactor = " << floatLiteral(e.rasterSlopeScaledDepthBias) << ";\n"
      << "shadowRaster.lineWidth = 1.0f;\n"
      << "// Depth-stencil state: depthTestEnable = VK_TRUE, depthWriteEnable = VK_TRUE, depthCompareOp = "
      << (e.reversedZ ? "VK_COMPARE_OP_GREATER; clear depth 0.0.\n\n" : "VK_COMPARE_OP_LESS; clear depth 1.0.\n\n");
    const char* filter = e.linearCompare ? "VK_FILTER_LINEAR" : "VK_FILTER_NEAREST";
    const char* address = addressName(e.sampler.addressMode, ExportFormat::Vulkan);
    std::string border = "VK_BORDER_COLOR_FLOAT_CUSTOM_EXT";
    if (e.borderStored == 1.0f) border = "VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE";
    if (e.borderStored == 0.0f) border = "VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK";
    if (border == "VK_BORDER_COLOR_FLOAT_CUSTOM_EXT")
        o << "// Border depth " << floatLiteral(e.borderStored)
          << ": chain VkSamplerCustomBorderColorCreateInfoEXT (VK_EXT_custom_border_color) with that value.\n";
    o << "VkSamplerCreateInfo shadowSampler = {VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};\n"
      << "shadowSampler.magFilter = " << filter << ";\n"
      << "shadowSampler.minFilter = " << filter << ";\n"
      << "shadowSampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;\n"
      << "shadowSampler.addressModeU = " << address << ";\n"
      << "shadowSampler.addressModeV = " << address << ";\n"
      << "shadowSampler.addressModeW = " << address << ";\n"
      << "shadowSampler.compareEnable = VK_TRUE;\n"
      << "shadowSampler.compareOp = " << (e.reversedZ ? "VK_COMPARE_OP_GREATER_OR_EQUAL" : "VK_COMPARE_OP_LESS_OR_EQUAL") << ";\n"
      << "shadowSampler.borderColor = " << border << ";\n"
      << "shadowSampler.maxLod = 0.0f;\n";
    if (e.lightType == LightType::Point)
        o << "// Image: arrayLayers = 6, flags VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT; render face f into layer f; sample it\n"
             "// through a VK_IMAGE_VIEW_TYPE_CUBE view.\n";
    o << viewsBlock(e, ExportFormat::Vulkan) << shaderBlock(e, ExportFormat::Vulkan);
    return o.str();
}

std::string gl(const ShadowExport& e) {
    const ShadowMapSettings& s = e.shadow;
    std::ostringstream o;
    o << conventions(e, ExportFormat::GL, "// ");
    if (!e.floatDepth)
        o << "// GL leaves a UNORM format's r to the implementation; Mesa and the common drivers use 1/(2^n - 1).\n";
    if (e.lightType == LightType::Point)
        o << "glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &shadowMap);  // face f is layer f: "
             "glNamedFramebufferTextureLayer(fbo, GL_DEPTH_ATTACHMENT, shadowMap, 0, f)\n"
             "glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // taps at a face's edge read the neighbouring face\n";
    o << "glTextureStorage2D(shadowMap, 1, " << formatName(e, ExportFormat::GL) << ", " << s.resolution << ", "
      << s.resolution << ");\n";
    if (e.reversedZ)
        o << "glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // while drawing the map; restore GL_NEGATIVE_ONE_TO_ONE after\n"
          << "glEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_GREATER);\nglClearDepth(0.0);\n";
    else
        o << "glEnable(GL_DEPTH_TEST);\nglDepthFunc(GL_LESS);\nglClearDepth(1.0);\n";
    o << (e.depthClamp ? "glEnable(GL_DEPTH_CLAMP);\n" : "glDisable(GL_DEPTH_CLAMP);\n");
    if (s.cullMode == CullMode::None)
        o << "glDisable(GL_CULL_FACE);\n";
    else
        o << "glEnable(GL_CULL_FACE);\nglCullFace(" << (s.cullMode == CullMode::Back ? "GL_BACK" : "GL_FRONT")
          << ");\nglFrontFace(GL_CCW);\n";
    if (s.depthBias == 0.0f && s.slopeScaledDepthBias == 0.0f) {
        o << "glDisable(GL_POLYGON_OFFSET_FILL);\n";
    } else {
        o << "glEnable(GL_POLYGON_OFFSET_FILL);\n"
          << "// factor = SlopeScaledDepthBias, units = DepthBias, clamp = DepthBiasClamp (GL 4.6 or\n"
          << "// GL_EXT_polygon_offset_clamp; without either: glPolygonOffset(factor, units), no clamp).\n"
          << "glPolygonOffsetClamp(" << floatLiteral(e.rasterSlopeScaledDepthBias) << ", "
          << floatLiteral(e.rasterDepthBias) << ", " << floatLiteral(e.rasterDepthBiasClamp) << ");\n";
    }
    const char* filter = e.linearCompare ? "GL_LINEAR" : "GL_NEAREST";
    const char* address = addressName(e.sampler.addressMode, ExportFormat::GL);
    const std::string border = floatLiteral(e.borderStored);
    o << "\nconst GLfloat shadowBorder[4] = {" << border << ", " << border << ", " << border << ", " << border << "};\n"
      << "glSamplerParameteri(shadowSampler, GL_TEXTURE_WRAP_S, " << address << ");\n"
      << "glSamplerParameteri(shadowSampler, GL_TEXTURE_WRAP_T, " << address << ");\n"
      << "glSamplerParameterfv(shadowSampler, GL_TEXTURE_BORDER_COLOR, shadowBorder);\n"
      << "glSamplerParameteri(shadowSampler, GL_TEXTURE_MIN_FILTER, " << filter << ");\n"
      << "glSamplerParameteri(shadowSampler, GL_TEXTURE_MAG_FILTER, " << filter << ");\n"
      << "glSamplerParameteri(shadowSampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);\n"
      << "glSamplerParameteri(shadowSampler, GL_TEXTURE_COMPARE_FUNC, " << (e.reversedZ ? "GL_GEQUAL" : "GL_LEQUAL") << ");\n";
    o << viewsBlock(e, ExportFormat::GL) << shaderBlock(e, ExportFormat::GL);
    return o.str();
}

nlohmann::json biasJson(const BiasTerm& t) { return {{"depth", t.depth}, {"world", t.world}, {"texels", t.texels}}; }

nlohmann::json jsonOf(const ShadowExport& e) {
    const ShadowMapSettings& s = e.shadow;
    nlohmann::json j;
    j["scene"] = e.sceneLabel;
    j["light"] = {{"index", e.lightIndex}, {"label", e.label}, {"type", lightTypeName(e.lightType)}};
    nlohmann::json views = nlohmann::json::array();
    for (const ExportView& v : e.views) {
        std::vector<double> m;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m.push_back(v.viewProjection[c][r]);
        nlohmann::json view = {{"label", v.label}, {"near", v.nearPlane}, {"far", v.farPlane},
                               {"texelWorldSize", v.texelWorldSize}, {"viewProjectionColumnMajor", m}};
        if (v.cubeFace >= 0) view["cubeFace"] = cubeFaces()[std::size_t(v.cubeFace)].name;
        view["normalOffsetWorld"] = v.normalOffsetWorld;
        if (v.cascade >= 0) {
            view["cascade"] = v.cascade;
            view["farDepth"] = v.farDepth;
            view["blendStart"] = v.blendStart;
            if (v.bias.valid)
                view["bias"] = {{"constantNear", biasJson(v.bias.constantNear)},
                                {"constantFar", biasJson(v.bias.constantFar)},
                                {"slope", biasJson(v.bias.slope)},
                                {"total", biasJson(v.bias.total)},
                                {"texelWorldSize", v.bias.texelWorldSize}};
        }
        views.push_back(view);
    }
    j["views"] = views;
    if (e.cascaded)  // the selection: a pixel's depth in front of this camera picks the cascade (view_select.glsl)
        j["cascades"] = {{"count", e.cascadeCount},
                         {"cameraEye", {e.camera.eye.x, e.camera.eye.y, e.camera.eye.z}},
                         {"cameraForward", {e.camera.forward.x, e.camera.forward.y, e.camera.forward.z}},
                         {"depth", "dot(worldPos - cameraEye, cameraForward), render-origin-relative"}};
    j["renderOrigin"] = {e.renderOrigin.x, e.renderOrigin.y, e.renderOrigin.z};
    j["depth"] = {{"format", formatName(e, ExportFormat::GL)},
                  {"bits", e.depthBits},
                  {"float", e.floatDepth},
                  {"resolution", s.resolution},
                  {"windowDepthRange", {0, 1}},
                  {"shadowLabClipDepthRange", e.reversedZ ? nlohmann::json{0, 1} : nlohmann::json{-1, 1}},
                  {"reversedZ", e.reversedZ},
                  {"compare", e.reversedZ ? "GREATER, cleared to 0" : "LESS, cleared to 1"},
                  {"minimumResolvableDifference", e.depthStep},
                  {"minimumResolvableDifferenceRule",
                   e.floatDepth ? "2^(exponent(max depth of the primitive) - 23); the value is for depths in [0.5,1)"
                                : "1/(2^bits - 1)"}};
    // The API's values: ShadowLab's settings negated for reversed-Z (shadowLabBias keeps the settings).
    j["rasterizer"] = {{"depthBias", e.rasterDepthBias},
                       {"d3dDepthBiasInt", e.d3dDepthBias},
                       {"slopeScaledDepthBias", e.rasterSlopeScaledDepthBias},
                       {"depthBiasClamp", e.rasterDepthBiasClamp},
                       {"shadowLabBias", {{"depthBias", s.depthBias},
                                          {"slopeScaledDepthBias", s.slopeScaledDepthBias},
                                          {"depthBiasClamp", s.depthBiasClamp}}},
                       {"cullMode", s.cullMode == CullMode::Back ? "back" : s.cullMode == CullMode::Front ? "front" : "none"},
                       {"frontFace", "counter-clockwise"},
                       {"depthClamp", e.depthClamp}};
    j["normalOffset"] = {{"texels", s.normalOffset},
                         {"world", e.normalOffsetWorld},
                         {"texelWorldSize", e.texelWorldSize},
                         {"perspective", e.perspective}};
    j["lightVolume"] = {{"near", e.nearPlane}, {"far", e.farPlane}};
    if (e.bias.valid)
        j["biasAtReceivers"] = {{"receiverDepthMin", e.bias.receiverDepthMin},
                                {"receiverDepthMax", e.bias.receiverDepthMax},
                                {"constantWorldNearest", e.bias.constantNear.world},
                                {"constantWorldFarthest", e.bias.constantFar.world},
                                {"slopeWorldMedian", e.bias.slope.world},
                                {"totalWorldMedian", e.bias.total.world},
                                {"totalTexelsMedian", e.bias.total.texels}};
    const char* address = e.sampler.addressMode == AddressMode::Wrap          ? "wrap"
                          : e.sampler.addressMode == AddressMode::ClampToEdge ? "clamp"
                                                                              : "border";
    j["sampler"] = {{"addressMode", address},
                    {"borderDepth", e.sampler.borderDepth},
                    {"borderStored", e.borderStored},  // what the sampler holds: 1 - borderDepth for reversed-Z
                    {"compare", e.reversedZ ? "GEQUAL" : "LEQUAL"},
                    {"filter", e.linearCompare ? "linear" : "nearest"}};
    const char* kind = filterTechnique(e.filter.kind).name;
    nlohmann::json taps = nlohmann::json::array();
    for (const FilterTap& tap : filterTaps(e.filter)) taps.push_back({tap.offsetTexels.x, tap.offsetTexels.y});
    j["filter"] = {{"kind", kind}, {"kernel", e.filter.kernel}, {"poissonRadiusTexels", e.filter.poissonRadius},
                   {"bilinear", e.linearCompare}, {"tapOffsetsTexels", taps}};
    j["receiverPlaneBias"] = {{"setting", s.receiverPlaneBias}, {"applied", e.receiverPlane}};
    if (e.momentTechnique || e.ownLookup) {  // the technique's own GLSL (OpenGL's: loose uniforms) and its numbers
        const glm::vec4& u = e.techniqueUniforms;
        nlohmann::json technique = {{"uTechnique", {u.x, u.y, u.z, u.w}},
                                    {"lightSpread", e.lightSpread},
                                    {"lookupGlsl", techniqueLookupCode(e, false)}};
        if (e.momentTechnique) {
            const MomentsPassShaders shaders = momentsPassShaders(e, false);
            nlohmann::json blur = nlohmann::json::array();
            for (const ExportView& v : e.views) {
                const std::vector<float> weights = blurWeights(v.blurTexels);
                blur.push_back({{"view", v.label}, {"widthTexels", v.blurTexels}, {"clamped", v.blurClamped},
                                {"radius", weights.size() / 2},
                                {"weights", std::vector<float>(weights.begin() + std::ptrdiff_t(weights.size() / 2), weights.end())}});
            }
            const glm::vec4& b = e.momentBorder;
            technique["moments"] = {{"format", e.momentFormat},
                                    {"glFormat", momentFormatName(e.momentFormat, ExportFormat::GL)},
                                    {"border", {b.x, b.y, b.z, b.w}},
                                    {"clamps", e.techniqueClamps},
                                    {"notExported", e.notExported},
                                    {"blur", blur},
                                    {"convertGlsl", shaders.convert},
                                    {"blurGlsl", shaders.blur},
                                    {"levels", momentLevels(e.shadow.resolution, e.filter.momentMips)},
                                    {"minFilter", e.filter.momentMips ? "linear-mipmap-linear" : "linear"}};
            if (e.filter.momentMips) technique["moments"]["mipsGlsl"] = shaders.mips;
        }
        j["technique"] = technique;
    }
    j["tapsKeptInsideTheMap"] = true;
    return j;
}

}  // namespace

std::string exportSnippet(const ShadowExport& values, ExportFormat format) {
    switch (format) {
        case ExportFormat::D3D12:
        case ExportFormat::D3D11: return d3d(values, format);
        case ExportFormat::Vulkan: return vulkan(values);
        case ExportFormat::GL: return gl(values);
        case ExportFormat::Json: return jsonOf(values).dump(2) + "\n";
    }
    return {};
}

}  // namespace shadowlab

namespace shadowlab {

std::string exportSnippet(const ShadowExportSet& set, ExportFormat format) {
    std::size_t casting = 0;
    for (const LightExport& l : set.lights) casting += l.shadow ? 1 : 0;
    const std::string scope = set.onlyLight ? "light " + std::to_string(*set.onlyLight) + " of " + set.lightSource
                                            : "every light: " + set.lightSource;
    const std::string nothing =
        set.lightCount == 0 ? "Nothing casts a shadow: the light set is empty, so there is no shadow pass, map or sampler "
                              "to export."
                            : "Nothing casts a shadow: no light " + std::string(set.onlyLight ? "asked for " : "") +
                                  "is enabled with castsShadows on, so there is no shadow pass, map or sampler to export.";
    if (format == ExportFormat::Json) {
        nlohmann::json j;
        j["scene"] = set.sceneLabel;
        j["lightSource"] = set.lightSource;
        j["lightCount"] = set.lightCount;
        if (set.onlyLight) j["onlyLight"] = *set.onlyLight;
        j["lights"] = nlohmann::json::array();
        for (const LightExport& l : set.lights) {
            nlohmann::json entry = l.shadow ? jsonOf(*l.shadow) : nlohmann::json::object();
            entry["index"] = l.index;
            entry["label"] = l.label;
            entry["type"] = lightTypeName(l.type);
            entry["castsShadow"] = l.shadow.has_value();
            if (!l.shadow) entry["noShadow"] = l.noShadowReason;
            j["lights"].push_back(entry);
        }
        if (casting == 0) j["note"] = nothing;
        return j.dump(2) + "\n";
    }
    std::ostringstream o;
    o << "// ShadowLab export for scene " << set.sceneLabel << ", " << scope << ".\n";
    if (set.lights.empty() || casting == 0) o << "// " << nothing << "\n";
    for (const LightExport& l : set.lights)
        o << "//   " << l.label << ": "
          << (!l.shadow ? l.noShadowReason
              : l.shadow->cascaded ? "casts (" + std::to_string(l.shadow->cascadeCount) + " cascades" +
                                         (l.shadow->views.size() < l.shadow->cascadeCount
                                              ? ", " + l.shadow->views.front().label.substr(l.shadow->label.size() + 1) +
                                                    " exported (--view)"
                                              : std::string()) + ")"
              : l.type == LightType::Point
                  ? "casts (" + (l.shadow->views.size() == 6 ? std::string("6 views: cube faces +X,-X,+Y,-Y,+Z,-Z")
                                                              : "face " + l.shadow->views.front().label.substr(
                                                                              l.shadow->views.front().label.size() - 2) +
                                                                    " of 6 (--view)") + ")"
                  : std::string("casts (1 view)"))
          << "\n";
    for (const LightExport& l : set.lights) {
        o << "\n// ======== " << l.label;
        if (!l.shadow) {
            o << ": " << l.noShadowReason << "; no shadow state ========\n";
            continue;
        }
        o << " ========\n" << exportSnippet(*l.shadow, format);
    }
    return o.str();
}

}  // namespace shadowlab
