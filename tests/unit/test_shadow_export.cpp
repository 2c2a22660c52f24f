// The export's numbers per depth format, in closed form: r, the D3D INT rounding, the Vulkan / GL values, the normal
// offset in world units, and the JSON carrying the same numbers. And the depth-format change that keeps DepthBias's
// world meaning.
#include "export/export_snippets.h"
#include "export/shadow_shader_code.h"
#include "light/depth_format_change.h"
#include "scene/builtin_scenes.h"
#include "shading/filter_taps.h"
#include "views/shadow_view.h"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

namespace shadowlab {
namespace {

// A directional light whose volume is 20 world units wide on a 2048 map: one texel = 20/2048 world units.
LightSpace orthoLight() {
    LightSpace light;
    light.orthoSize = 20.0;
    light.resolution = 2048;
    light.texelWorldSize = 20.0 / 2048.0;
    light.nearPlane = 0.0;
    light.farPlane = 30.0;
    return light;
}

Settings withBias(DepthFormat format, float depthBias) {
    Settings s;
    s.lights[0].shadow.format = format;
    s.lights[0].shadow.depthBias = depthBias;
    s.lights[0].shadow.slopeScaledDepthBias = 1.25f;
    s.lights[0].shadow.depthBiasClamp = 0.001f;
    s.lights[0].shadow.normalOffset = 0.5f;
    s.lights[0].shadow.cullMode = CullMode::Front;
    return s;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ShadowExport, MinimumResolvableDifferencePerFormat) {
    EXPECT_DOUBLE_EQ(makeShadowExport(withBias(DepthFormat::D16, 2), 0, orthoLight(), "t").depthStep, 1.0 / 65535.0);
    EXPECT_DOUBLE_EQ(makeShadowExport(withBias(DepthFormat::D24, 2), 0, orthoLight(), "t").depthStep, 1.0 / 16777215.0);
    EXPECT_DOUBLE_EQ(makeShadowExport(withBias(DepthFormat::D32F, 2), 0, orthoLight(), "t").depthStep, std::ldexp(1.0, -24));
}

TEST(ShadowExport, D16SnippetsCarryTheFormatsNumbers) {
    const ShadowExport e = makeShadowExport(withBias(DepthFormat::D16, 1.5f), 0, orthoLight(), "builtin:test");
    const std::string d3d12 = exportSnippet(e, ExportFormat::D3D12);
    EXPECT_TRUE(contains(d3d12, "DXGI_FORMAT_D16_UNORM")) << d3d12;
    EXPECT_TRUE(contains(d3d12, "r = 1/(2^16 - 1) = 1.5259e-05")) << d3d12;
    EXPECT_TRUE(contains(d3d12, "shadowRaster.DepthBias = 2;")) << "INT DepthBias rounds 1.5 half away from zero";
    EXPECT_TRUE(contains(d3d12, "1.5 rounds to 2 (off by 0.5 r)")) << d3d12;
    EXPECT_TRUE(contains(d3d12, "FLOAT DepthBias = 1.5f")) << "D3D12_RASTERIZER_DESC1 takes the exact value";
    EXPECT_TRUE(contains(d3d12, "shadowRaster.SlopeScaledDepthBias = 1.25f;"));
    EXPECT_TRUE(contains(d3d12, "shadowRaster.DepthBiasClamp = 0.001f;"));
    EXPECT_TRUE(contains(d3d12, "shadowRaster.CullMode = D3D12_CULL_MODE_FRONT;"));
    EXPECT_TRUE(contains(d3d12, "shadowRaster.DepthClipEnable = FALSE;")) << "depth clamp on by default";
    EXPECT_TRUE(contains(d3d12, "D3D12_COMPARISON_FUNC_LESS_EQUAL"));
    const std::string d3d11 = exportSnippet(e, ExportFormat::D3D11);
    EXPECT_TRUE(contains(d3d11, "D3D11_RASTERIZER_DESC shadowRaster")) << d3d11;
    EXPECT_TRUE(contains(d3d11, "shadowRaster.CullMode = D3D11_CULL_FRONT;"));
    EXPECT_TRUE(contains(d3d11, "D3D11_FILTER_COMPARISON_MIN_MAG_MIP_POINT")) << "PCF 3x3 compares single texels";
    const std::string vk = exportSnippet(e, ExportFormat::Vulkan);
    EXPECT_TRUE(contains(vk, "VK_FORMAT_D16_UNORM"));
    EXPECT_TRUE(contains(vk, "shadowRaster.depthBiasConstantFactor = 1.5f;")) << vk;
    EXPECT_TRUE(contains(vk, "shadowRaster.depthBiasSlopeFactor = 1.25f;"));
    EXPECT_TRUE(contains(vk, "shadowRaster.depthBiasClamp = 0.001f;"));
    EXPECT_TRUE(contains(vk, "shadowRaster.cullMode = VK_CULL_MODE_FRONT_BIT;"));
    EXPECT_TRUE(contains(vk, "shadowRaster.frontFace = VK_FRONT_FACE_CLOCKWISE;"));
    EXPECT_TRUE(contains(vk, "needs VkPhysicalDeviceFeatures::depthBiasClamp"));
    EXPECT_TRUE(contains(vk, "depthBiasExact = VK_TRUE")) << "how to pin a UNORM format's r in Vulkan";
    const std::string gl = exportSnippet(e, ExportFormat::GL);
    EXPECT_TRUE(contains(gl, "GL_DEPTH_COMPONENT16, 2048, 2048"));
    EXPECT_TRUE(contains(gl, "glPolygonOffsetClamp(1.25f, 1.5f, 0.001f);")) << gl;
    EXPECT_TRUE(contains(gl, "glCullFace(GL_FRONT);"));
    EXPECT_TRUE(contains(gl, "clip depth [-1,1] (no glClipControl)"));
}

TEST(ShadowExport, D24AndD32FState) {
    const std::string d24 = exportSnippet(makeShadowExport(withBias(DepthFormat::D24, 3), 0, orthoLight(), "t"),
                                          ExportFormat::D3D11);
    EXPECT_TRUE(contains(d24, "DXGI_FORMAT_D24_UNORM_S8_UINT")) << d24;
    EXPECT_TRUE(contains(d24, "r = 1/(2^24 - 1) = 5.96046e-08"));
    EXPECT_TRUE(contains(d24, "shadowRaster.DepthBias = 3;"));
    EXPECT_FALSE(contains(d24, "is an INT here")) << "an integral DepthBias needs no note";
    const std::string d32 = exportSnippet(makeShadowExport(withBias(DepthFormat::D32F, 2), 0, orthoLight(), "t"),
                                          ExportFormat::D3D12);
    EXPECT_TRUE(contains(d32, "DXGI_FORMAT_D32_FLOAT"));
    EXPECT_TRUE(contains(d32, "2^(exponent(max depth of the primitive) - 23)")) << "D3D's float-format rule";
    EXPECT_TRUE(contains(d32, "2^-24 = 5.96046e-08 for depths in [0.5,1)"));
    EXPECT_TRUE(contains(d32, "NOT reversed-Z"));
    EXPECT_TRUE(contains(d32, "clip depth [0,1]"));
}

TEST(ShadowExport, NormalOffsetInWorldUnitsAndJsonCarryTheSameNumbers) {
    Settings s = withBias(DepthFormat::D32F, 2);
    s.sampler.addressMode = AddressMode::ClampToEdge;
    s.filter.kind = FilterKind::Poisson;
    const ShadowExport e = makeShadowExport(s, 0, orthoLight(), "builtin:test");
    EXPECT_DOUBLE_EQ(e.normalOffsetWorld, 0.5 * 20.0 / 2048.0);
    const std::string gl = exportSnippet(e, ExportFormat::GL);
    EXPECT_TRUE(contains(gl, "0.5 texels = 0.00488281 world units")) << gl;
    EXPECT_TRUE(contains(gl, "for scene builtin:test"));
    EXPECT_TRUE(contains(gl, "GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE"));
    EXPECT_TRUE(contains(gl, "GL_TEXTURE_MIN_FILTER, GL_LINEAR")) << "Poisson taps compare bilinearly";
    const nlohmann::json j = nlohmann::json::parse(exportSnippet(e, ExportFormat::Json));
    EXPECT_DOUBLE_EQ(j["normalOffset"]["world"].get<double>(), 0.5 * 20.0 / 2048.0);
    EXPECT_DOUBLE_EQ(j["depth"]["minimumResolvableDifference"].get<double>(), std::ldexp(1.0, -24));
    EXPECT_EQ(j["rasterizer"]["depthBias"].get<float>(), 2.0f);
    EXPECT_EQ(j["rasterizer"]["cullMode"], "front");
    EXPECT_EQ(j["sampler"]["addressMode"], "clamp");
    EXPECT_EQ(j["sampler"]["filter"], "linear");
    EXPECT_EQ(j["depth"]["reversedZ"], false);
}

TEST(ShadowExport, ReversedZSnippetsNegateTheBiasAndCompareGreater) {
    Settings s = withBias(DepthFormat::D24, 3);
    s.lights[0].shadow.reversedZ = true;
    LightSpace light = orthoLight();
    light.reversedZ = true;
    const ShadowExport e = makeShadowExport(s, 0, light, "t");
    const std::string d3d = exportSnippet(e, ExportFormat::D3D12);
    EXPECT_TRUE(contains(d3d, "REVERSED-Z (near 1, far 0)")) << d3d;
    EXPECT_TRUE(contains(d3d, "shadowRaster.DepthBias = -3;"));
    EXPECT_TRUE(contains(d3d, "shadowRaster.SlopeScaledDepthBias = -1.25f;"));
    EXPECT_TRUE(contains(d3d, "shadowRaster.DepthBiasClamp = -0.001f;")) << "a negative clamp bounds a negative bias";
    EXPECT_TRUE(contains(d3d, "COMPARISON_FUNC_GREATER_EQUAL"));
    EXPECT_TRUE(contains(d3d, "BorderColor[3] = 0.0f;")) << "border depth 1 (lit outside) is stored as 0";
    const std::string vk = exportSnippet(e, ExportFormat::Vulkan);
    EXPECT_TRUE(contains(vk, "shadowRaster.depthBiasConstantFactor = -3.0f;")) << vk;
    EXPECT_TRUE(contains(vk, "VK_COMPARE_OP_GREATER_OR_EQUAL"));
    EXPECT_TRUE(contains(vk, "depthCompareOp = VK_COMPARE_OP_GREATER; clear depth 0.0"));
    EXPECT_TRUE(contains(vk, "VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK"));
    const std::string gl = exportSnippet(e, ExportFormat::GL);
    EXPECT_TRUE(contains(gl, "glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)")) << gl;
    EXPECT_TRUE(contains(gl, "glDepthFunc(GL_GREATER);\nglClearDepth(0.0);"));
    EXPECT_TRUE(contains(gl, "glPolygonOffsetClamp(-1.25f, -3.0f, -0.001f);"));
    EXPECT_TRUE(contains(gl, "GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL"));
    const nlohmann::json j = nlohmann::json::parse(exportSnippet(e, ExportFormat::Json));
    EXPECT_EQ(j["depth"]["reversedZ"], true);
    EXPECT_EQ(j["rasterizer"]["depthBias"].get<float>(), -3.0f);
    EXPECT_EQ(j["rasterizer"]["shadowLabBias"]["depthBias"].get<float>(), 3.0f);
    EXPECT_EQ(j["sampler"]["compare"], "GEQUAL");
    EXPECT_EQ(j["sampler"]["borderStored"].get<float>(), 0.0f);
    // The normal convention is untouched: positive values, LEQUAL.
    const std::string normal = exportSnippet(makeShadowExport(withBias(DepthFormat::D24, 3), 0, orthoLight(), "t"),
                                             ExportFormat::GL);
    EXPECT_TRUE(contains(normal, "glPolygonOffsetClamp(1.25f, 3.0f, 0.001f);")) << normal;
    EXPECT_FALSE(contains(normal, "GL_ZERO_TO_ONE);  // while drawing the map")) << "no clip control call";
}

TEST(ShadowExport, FormatNamesParse) {
    EXPECT_EQ(parseExportFormat("vulkan"), ExportFormat::Vulkan);
    EXPECT_EQ(parseExportFormat("d3d11"), ExportFormat::D3D11);
    EXPECT_FALSE(parseExportFormat("Vulkan").has_value());
    EXPECT_FALSE(parseExportFormat("d3d9").has_value());
}

// A directional, a spot and a point light over builtin:textbook; light 1's DepthBias 7 marks its section.
Settings threeLights() {
    Settings s;
    s.lights.resize(3);
    s.lights[1].type = LightType::Spot;
    s.lights[1].position = {0.0f, 6.0f, 0.0f};
    s.lights[1].direction = {0.0f, -1.0f, 0.1f};
    s.lights[1].shadow.depthBias = 7.0f;
    s.lights[2].type = LightType::Point;
    s.lights[2].position = {0.0f, 3.0f, 0.0f};
    s.lights[2].shadow.depthBias = 5.0f;
    return s;
}

ShadowExportSet exportSet(const Settings& s, std::optional<std::size_t> only = std::nullopt) {
    const std::optional<Scene> scene = makeBuiltinScene("textbook");
    std::string error;
    const std::optional<ShadowExportSet> set = exportForScene(s, *scene, "builtin:textbook", only, error);
    EXPECT_TRUE(set.has_value()) << error;
    return set.value_or(ShadowExportSet{});
}

std::size_t count(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

// Issue 20: a cascaded light exports every cascade (matrix, split, bias in its own texels) and the selection as
// ShadowLab's own GLSL (shaders/shadow/view_select.glsl as it is); --view exports one cascade; without a camera it
// says why it cannot.
TEST(ShadowExportLights, ACascadedLightExportsEveryCascadeAndTheSelection) {
    const std::optional<Scene> scene = makeBuiltinScene("textbook");
    Settings s;
    s.lights[0].projection.fit = ProjectionFit::Cascades;
    s.lights[0].projection.cascadeCount = 3;
    s.lights[0].projection.shadowDistance = 30.0f;
    s.lights[0].projection.blendBand = 0.2f;
    s.lights[0].shadow.normalOffset = 0.5f;
    s.camera.autoFrame = false;
    ViewCamera camera;  // near the floor looking across it, render-origin-relative
    camera.eye = glm::dvec3(-4.0, 1.2, 9.0) - renderOriginOf(scene->bounds);
    camera.forward = glm::normalize(glm::dvec3(5.0, -0.9, -12.0));
    camera.right = glm::normalize(glm::cross(camera.forward, glm::dvec3(0.0, 1.0, 0.0)));
    camera.up = glm::cross(camera.right, camera.forward);
    camera.aspect = 16.0 / 9.0;
    camera.farPlane = 100.0;
    std::string error;
    EXPECT_FALSE(exportForScene(s, *scene, "builtin:textbook", std::nullopt, error));
    EXPECT_NE(error.find("lights.0"), std::string::npos) << error;

    std::optional<ShadowExportSet> set = exportForScene(s, *scene, "builtin:textbook", std::nullopt, error, &camera);
    ASSERT_TRUE(set) << error;
    const ShadowExport& e = *set->lights.at(0).shadow;
    ASSERT_TRUE(e.cascaded);
    ASSERT_EQ(e.views.size(), 3u);
    for (std::size_t c = 0; c < 3; ++c) {
        const ExportView& v = e.views[c];
        EXPECT_EQ(v.cascade, int(c));
        EXPECT_EQ(v.label, "light 0 (directional) cascade:" + std::to_string(c));
        EXPECT_DOUBLE_EQ(v.normalOffsetWorld, 0.5 * v.texelWorldSize);
        if (c < 2) EXPECT_LT(v.blendStart, v.farDepth) << "a band into the next";
        else EXPECT_EQ(v.blendStart, v.farDepth) << "the last cascade has no next";
        if (v.bias.valid) EXPECT_DOUBLE_EQ(v.bias.texelWorldSize, v.texelWorldSize);
        if (c > 0) {
            EXPECT_GT(v.farDepth, e.views[c - 1].farDepth);
            EXPECT_GT(v.texelWorldSize, e.views[c - 1].texelWorldSize);
        }
    }
    const std::string gl = exportSnippet(*set, ExportFormat::GL);
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(contains(gl, "light0Cascade" + std::to_string(c) + "ViewProjection[16]")) << gl;
    EXPECT_TRUE(contains(gl, "fading into cascade:1 from ")) << gl;
    EXPECT_TRUE(contains(gl, "casts (3 cascades)")) << gl;
    std::ifstream in(std::string(SHADOWLAB_SOURCE_DIR) + "/shaders/shadow/view_select.glsl");
    std::stringstream selection;
    selection << in.rdbuf();
    ASSERT_FALSE(selection.str().empty());
    EXPECT_TRUE(contains(gl, selection.str())) << "the selection is the main pass's file, as it is";
    EXPECT_TRUE(contains(gl, "CascadeChoice light0Cascade(vec3 worldPos)")) << gl;
    const std::string d3d = exportSnippet(*set, ExportFormat::D3D12);
    EXPECT_TRUE(contains(d3d, "// CascadeChoice selectCascade(")) << "HLSL: the GLSL selection as a comment";
    const nlohmann::json j = nlohmann::json::parse(exportSnippet(*set, ExportFormat::Json));
    const nlohmann::json& views = j["lights"][0]["views"];
    ASSERT_EQ(views.size(), 3u);
    EXPECT_EQ(views[2]["cascade"], 2);
    EXPECT_DOUBLE_EQ(views[1]["farDepth"].get<double>(), e.views[1].farDepth);
    EXPECT_EQ(j["lights"][0]["cascades"]["count"], 3);

    // --view: one cascade; a view the light does not have names the light, its view count and the allowed values.
    set = exportForScene(s, *scene, "builtin:textbook", 0, error, &camera, "cascade:1");
    ASSERT_TRUE(set) << error;
    ASSERT_EQ(set->lights[0].shadow->views.size(), 1u);
    EXPECT_EQ(set->lights[0].shadow->views[0].cascade, 1);
    EXPECT_TRUE(contains(exportSnippet(*set, ExportFormat::GL), "One cascade of 3 exported (--view)"));
    EXPECT_FALSE(exportForScene(s, *scene, "builtin:textbook", 0, error, &camera, "cascade:3"));
    EXPECT_EQ(error, "--view cascade:3: light 0 has no such view: it has 3 views (allowed: cascade:0, cascade:1, cascade:2)");
    EXPECT_FALSE(exportForScene(s, *scene, "builtin:textbook", std::nullopt, error, &camera, "cascade:1"));
    EXPECT_NE(error.find("--light N"), std::string::npos) << error;
}

TEST(ShadowExportLights, EveryLightIsExportedUnderItsOwnLabel) {
    const ShadowExportSet set = exportSet(threeLights());
    ASSERT_EQ(set.lights.size(), 3u);
    EXPECT_EQ(set.lightCount, 3u);
    for (const LightExport& l : set.lights) ASSERT_TRUE(l.shadow.has_value()) << l.label;
    EXPECT_EQ(set.lights[0].label, "light 0 (directional)");
    EXPECT_EQ(set.lights[1].label, "light 1 (spot)");
    EXPECT_EQ(set.lights[2].label, "light 2 (point)");
    EXPECT_EQ(set.lights[1].shadow->shadow.depthBias, 7.0f) << "light 1's own settings, not light 0's";
    EXPECT_FALSE(set.lights[1].shadow->depthClamp) << "depth clamp applies to directional views only";
    EXPECT_TRUE(set.lights[0].shadow->depthClamp);
    for (ExportFormat f : {ExportFormat::D3D12, ExportFormat::D3D11, ExportFormat::Vulkan, ExportFormat::GL}) {
        const std::string text = exportSnippet(set, f);
        EXPECT_TRUE(contains(text, "// ======== light 0 (directional) ========")) << text;
        EXPECT_TRUE(contains(text, "// ======== light 1 (spot) ========"));
        EXPECT_TRUE(contains(text, "// ======== light 2 (point) ========"));
        // Each section's state is its own light's: light 0's DepthBias 2, light 1's 7, light 2's 5.
        const std::size_t at1 = text.find("======== light 1"), at2 = text.find("======== light 2");
        const std::string section1 = text.substr(at1, at2 - at1);
        if (f == ExportFormat::Vulkan) {
            EXPECT_TRUE(contains(section1, "depthBiasConstantFactor = 7.0f;")) << section1;
            EXPECT_TRUE(contains(section1, "depthClampEnable = VK_FALSE;"));
            EXPECT_TRUE(contains(text.substr(at2), "depthBiasConstantFactor = 5.0f;"));
            EXPECT_TRUE(contains(text.substr(0, at1), "depthBiasConstantFactor = 2.0f;"));
        }
        if (f == ExportFormat::D3D12) EXPECT_TRUE(contains(section1, "shadowRaster.DepthBias = 7;")) << section1;
    }
    const nlohmann::json j = nlohmann::json::parse(exportSnippet(set, ExportFormat::Json));
    ASSERT_EQ(j["lights"].size(), 3u);
    EXPECT_EQ(j["lights"][1]["label"], "light 1 (spot)");
    EXPECT_EQ(j["lights"][1]["rasterizer"]["depthBias"].get<float>(), 7.0f);
    EXPECT_EQ(j["lights"][2]["type"], "point");
    EXPECT_EQ(j["lights"][2]["views"].size(), 6u);
}

TEST(ShadowExportLights, APointLightHasSixFacesWithTheirMatricesNearAndFar) {
    const ShadowExportSet set = exportSet(threeLights(), 2);
    ASSERT_EQ(set.lights.size(), 1u);
    const ShadowExport& e = *set.lights[0].shadow;
    ASSERT_EQ(e.views.size(), 6u);
    const char* names[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    const glm::dvec3 look[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; ++f) {
        const ExportView& v = e.views[std::size_t(f)];
        EXPECT_EQ(v.label, std::string("light 2 (point) face ") + names[f]);
        EXPECT_EQ(v.cubeFace, f);
        EXPECT_GT(v.farPlane, v.nearPlane);
        EXPECT_EQ(v.nearPlane, e.views[0].nearPlane);
        // A point on the face's axis projects to the face's centre, in front of the light (depth in (0, 1)).
        const glm::dvec4 clip = v.viewProjection * glm::dvec4(e.lightPosition + look[f] * 2.0, 1.0);
        EXPECT_NEAR(clip.x / clip.w, 0.0, 1e-9) << names[f];
        EXPECT_NEAR(clip.y / clip.w, 0.0, 1e-9) << names[f];
        EXPECT_GT(clip.w, 0.0) << names[f];
    }
    const std::string gl = exportSnippet(set, ExportFormat::GL);
    for (const char* n : {"PX", "NX", "PY", "NY", "PZ", "NZ"})
        EXPECT_EQ(count(gl, std::string("static const float light2Face") + n + "ViewProjection[16]"), 1u) << n << gl;
    for (const char* n : names) EXPECT_TRUE(contains(gl, std::string("// View light 2 (point) face ") + n + ": near ")) << n;
    EXPECT_TRUE(contains(gl, "GL_TEXTURE_CUBE_MAP")) << gl;
    // The taps' directions and per-face reference depth are the renderer's cube_face_depth.glsl, printed once.
    EXPECT_EQ(count(gl, "#ifndef SHADOWLAB_SHADOW_CUBE_FACE_DEPTH_GLSL"), 1u) << gl;
    EXPECT_EQ(count(gl, "CubeFaceFrame cubeFaceFrame(vec3 fromLight, LightData L)"), 1u);
    EXPECT_TRUE(contains(gl, "vec3 d = cubeFaceTap(frame, LIGHT2_TAP_OFFSETS[i]);"));
    EXPECT_TRUE(contains(gl, "float ref = clampToFar(L, faceDepth(v, d, L));"));
    EXPECT_TRUE(contains(gl, "texture(map, vec4(d, ref))"));
    const std::string d3d = exportSnippet(set, ExportFormat::D3D12);
    EXPECT_TRUE(contains(d3d, "FrontCounterClockwise = FALSE")) << "D3D cube faces: clip y negated";
    EXPECT_TRUE(contains(d3d, "TextureCube<float> map"));
    EXPECT_TRUE(contains(d3d, "cube faces with clip y negated"));
}

TEST(ShadowExportLights, ReceiverPlaneBiasIsShaderCodeWhenOnAndAbsentWhenOff) {
    Settings s;
    s.filter.kind = FilterKind::Pcf;
    s.filter.kernel = 5;
    s.lights[0].shadow.receiverPlaneBias = false;
    const std::string off = exportSnippet(exportSet(s), ExportFormat::Vulkan);
    EXPECT_FALSE(contains(off, "ReceiverPlaneSlope")) << off;
    EXPECT_TRUE(contains(off, "Receiver-plane depth bias: off"));
    EXPECT_TRUE(contains(off, "float light0Shadow(sampler2DShadow map")) << "the filter's tap loop is shader code too";
    EXPECT_TRUE(contains(off, "const int LIGHT0_TAPS = 25;"));
    s.lights[0].shadow.receiverPlaneBias = true;
    const ShadowExportSet set = exportSet(s);
    const std::string glsl = exportSnippet(set, ExportFormat::Vulkan);
    EXPECT_TRUE(contains(glsl, "vec2 light0ReceiverPlaneSlope(mat4 viewProjection")) << glsl;
    EXPECT_TRUE(contains(glsl, "dFdx(worldPos)"));
    EXPECT_TRUE(contains(glsl, "toCentre = floor(lookupTexels + offset)")) << "PCF reads single texels: the plane at the centre";
    EXPECT_TRUE(contains(glsl, "Receiver-plane depth bias: ON"));
    const std::string hlsl = exportSnippet(set, ExportFormat::D3D11);
    EXPECT_TRUE(contains(hlsl, "float2 light0ReceiverPlaneSlope(float4x4 viewProjection")) << hlsl;
    EXPECT_TRUE(contains(hlsl, "rsqrt(length2)"));
    EXPECT_TRUE(contains(hlsl, "map.SampleCmpLevelZero(cmp, tapTex, tapRef)"));
    EXPECT_TRUE(contains(hlsl, "0.5 - ndc.y * 0.5")) << "D3D's row 0 is clip y +1";
    EXPECT_FALSE(contains(hlsl, "vec2")) << "no GLSL in the HLSL snippet";
    const nlohmann::json j = nlohmann::json::parse(exportSnippet(set, ExportFormat::Json));
    EXPECT_EQ(j["lights"][0]["receiverPlaneBias"]["applied"], true);
    // A single centred tap has nothing to tilt: set, but (as in ShadowLab) not applied and no code.
    s.filter.kind = FilterKind::Point;
    const std::string point = exportSnippet(exportSet(s), ExportFormat::GL);
    EXPECT_FALSE(contains(point, "ReceiverPlaneSlope")) << point;
    EXPECT_TRUE(contains(point, "set, but not applied"));
}

TEST(ShadowExportLights, ShaderCodeUsesTheRendererTapsAndTheMainPassConstants) {
    Settings s;
    s.filter.kind = FilterKind::Poisson;
    s.filter.poissonRadius = 1.5f;
    const ShadowExportSet set = exportSet(s);
    const std::string glsl = exportSnippet(set, ExportFormat::GL);
    const std::vector<FilterTap> taps = filterTaps(s.filter);
    ASSERT_EQ(taps.size(), std::size_t(kPoissonTaps));
    char first[80];
    std::snprintf(first, sizeof first, "vec2(%.9g, %.9g)", taps[0].offsetTexels.x, taps[0].offsetTexels.y);
    const float x = float(taps[0].offsetTexels.x);
    EXPECT_TRUE(contains(glsl, "const vec2 LIGHT0_TAP_OFFSETS[16] = vec2[](vec2(")) << glsl;
    const std::size_t at = glsl.find("LIGHT0_TAP_OFFSETS[16] = vec2[](vec2(") + 37;
    EXPECT_EQ(std::strtof(glsl.c_str() + at, nullptr), x) << "the first tap is the renderer's";
    // The receiver-plane constants are the main pass's 2D comparisons': read them from the shader file they are in.
    std::ifstream in(std::string(SHADOWLAB_SOURCE_DIR) + "/shaders/shadow/compare_2d.glsl");
    std::stringstream shader;
    shader << in.rdbuf();
    std::smatch m;
    const std::string text = shader.str();
    ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(kReceiverPlaneMaxSlope = ([0-9.eE+-]+);)")));
    EXPECT_DOUBLE_EQ(std::stod(m[1]), kExportReceiverPlaneMaxSlope);
    ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(abs\(det\) > ([0-9.eE+-]+) \*)")));
    EXPECT_DOUBLE_EQ(std::stod(m[1]), kExportReceiverPlaneSingular);
}

TEST(ShadowExportLights, LightOptionExportsThatLightAloneAndRefusesOneThatDoesNotExist) {
    const ShadowExportSet one = exportSet(threeLights(), 1);
    ASSERT_EQ(one.lights.size(), 1u);
    EXPECT_EQ(one.lights[0].label, "light 1 (spot)");
    const std::string text = exportSnippet(one, ExportFormat::GL);
    EXPECT_TRUE(contains(text, "light 1 of")) << text;
    EXPECT_FALSE(contains(text, "light 0 (directional)"));
    EXPECT_FALSE(contains(text, "light 2 (point)"));
    const std::optional<Scene> scene = makeBuiltinScene("textbook");
    std::string error;
    EXPECT_FALSE(exportForScene(threeLights(), *scene, "t", 5, error).has_value());
    EXPECT_TRUE(contains(error, "lights.5")) << error;
    EXPECT_TRUE(contains(error, "0..2")) << error;
}

TEST(ShadowExportLights, DisabledAndNonCastingLightsAreListedWithoutShadowState) {
    Settings s = threeLights();
    s.lights[1].enabled = false;
    s.lights[2].castsShadows = false;
    const ShadowExportSet set = exportSet(s);
    ASSERT_EQ(set.lights.size(), 3u);
    EXPECT_FALSE(set.lights[1].shadow.has_value());
    EXPECT_FALSE(set.lights[2].shadow.has_value());
    const std::string vk = exportSnippet(set, ExportFormat::Vulkan);
    EXPECT_TRUE(contains(vk, "light 1 (spot): disabled")) << vk;
    EXPECT_TRUE(contains(vk, "light 2 (point): casts no shadow"));
    EXPECT_EQ(count(vk, "VkPipelineRasterizationStateCreateInfo"), 1u) << "only light 0 has a shadow pass";
    const nlohmann::json j = nlohmann::json::parse(exportSnippet(set, ExportFormat::Json));
    EXPECT_EQ(j["lights"][1]["castsShadow"], false);
    EXPECT_TRUE(j["lights"][1].contains("noShadow"));
}

TEST(ShadowExportLights, ZeroLightsSayThatNothingCasts) {
    Settings s;
    s.lights.clear();
    const ShadowExportSet set = exportSet(s);
    EXPECT_TRUE(set.lights.empty());
    for (ExportFormat f : {ExportFormat::D3D12, ExportFormat::D3D11, ExportFormat::Vulkan, ExportFormat::GL})
        EXPECT_TRUE(contains(exportSnippet(set, f), "Nothing casts a shadow: the light set is empty"));
    const nlohmann::json j = nlohmann::json::parse(exportSnippet(set, ExportFormat::Json));
    EXPECT_TRUE(j["lights"].empty());
    EXPECT_TRUE(contains(j["note"].get<std::string>(), "Nothing casts a shadow"));
    const std::optional<Scene> scene = makeBuiltinScene("textbook");
    std::string error;
    EXPECT_FALSE(exportForScene(s, *scene, "t", 0, error).has_value());
    EXPECT_TRUE(contains(error, "lights.0")) << error;
}

TEST(DepthFormatChange, D32fToD16KeepsTheDepthOffsetAtTheReceivers) {
    ShadowMapSettings shadow;
    shadow.format = DepthFormat::D32F;
    shadow.depthBias = 2.0f;
    const DepthFormatChange toD16 = changeDepthFormat(shadow, DepthFormat::D16, 0.75);
    EXPECT_EQ(toD16.shadow.format, DepthFormat::D16);
    // Same depth offset: 2 x 2^-24 == new x 1/65535, i.e. new = 2 x 65535 / 2^24 = 0.0078124.
    EXPECT_NEAR(double(toD16.shadow.depthBias), 2.0 * 65535.0 / 16777216.0, 1e-9);
    EXPECT_EQ(toD16.note, "DepthBias 2 (d32f) -> 0.007812 (d16), same world bias");
    EXPECT_EQ(toD16.shadow.slopeScaledDepthBias, shadow.slopeScaledDepthBias) << "window depth in every format";
    // And back: the number returns.
    EXPECT_NEAR(double(changeDepthFormat(toD16.shadow, DepthFormat::D32F, 0.75).shadow.depthBias), 2.0, 1e-5);
    // D32F's r halves below depth 0.5: receivers there need twice the units for the same offset.
    shadow.format = DepthFormat::D16;
    shadow.depthBias = 1.0f;
    EXPECT_NEAR(double(changeDepthFormat(shadow, DepthFormat::D32F, 0.3).shadow.depthBias), 33554432.0 / 65535.0, 1e-2);
    EXPECT_NEAR(double(changeDepthFormat(shadow, DepthFormat::D32F, 0.75).shadow.depthBias), 16777216.0 / 65535.0, 1e-2);
    // Reversed-Z without known receivers: they are taken at stored depth 0.25 (the mirror of 0.75), where D32F's r
    // is 2^-25, half of its step at 0.75: twice the units.
    shadow.reversedZ = true;
    EXPECT_NEAR(double(changeDepthFormat(shadow, DepthFormat::D32F, std::nullopt).shadow.depthBias),
                2.0 * 16777216.0 / 65535.0, 1e-2);
}

TEST(DepthFormatChange, NoBiasOrSameFormatChangesNothingButTheFormat) {
    ShadowMapSettings shadow;
    shadow.depthBias = 0.0f;
    const DepthFormatChange c = changeDepthFormat(shadow, DepthFormat::D16, 0.75);
    EXPECT_EQ(c.shadow.depthBias, 0.0f);
    EXPECT_EQ(c.note, "");
    shadow.depthBias = 2.0f;
    EXPECT_EQ(changeDepthFormat(shadow, shadow.format, 0.75).note, "");
}

// filter.momentMips is exported: the mips pass (ShadowLab's moments.comp.glsl MIPS, one level per dispatch), the
// storage's levels and trilinear sampler, and the lookup compiled with MOMENT_MIPS (the level from the pixel's
// footprint, so the function takes the position's screen derivatives). It used to be named under "Not exported";
// a setting the export cannot write is still named there (notExported), none is today.
TEST(ShadowExportTechniques, MomentMipsAreExportedAsAPassAndTheFootprintLookup) {
    Settings s;
    s.filter.kind = FilterKind::Vsm;
    s.lights[0].shadow.resolution = 512;
    for (const bool mips : {false, true}) {
        SCOPED_TRACE(mips ? "mips" : "no mips");
        s.filter.momentMips = mips;
        const ShadowExportSet set = exportSet(s);
        ASSERT_FALSE(set.lights.empty());
        ASSERT_TRUE(set.lights[0].shadow.has_value());
        for (const ExportFormat api : {ExportFormat::GL, ExportFormat::Vulkan}) {
            const std::string glsl = exportSnippet(set, api);
            EXPECT_EQ(count(glsl, "// Not exported:"), 0u);
            EXPECT_EQ(count(glsl, "static const char* light0MomentsMips = R\"glsl("), mips ? 1u : 0u);
            EXPECT_EQ(count(glsl, "#define MIPS"), mips ? 1u : 0u) << "the mips pass is moments.comp.glsl's MIPS";
            EXPECT_EQ(count(glsl, "10 mip levels (filter.momentMips)"), mips ? 1u : 0u) << "512 down to 1: 10 levels";
            EXPECT_EQ(count(glsl, "#define MOMENT_MIPS"), mips ? 1u : 0u) << "the lookup reads the footprint's level";
            if (api == ExportFormat::Vulkan)  // each descriptor listed once (uIn is declared in two branches)
                EXPECT_EQ(count(glsl, "binding 1 = readonly image2D uIn"), mips ? 2u : 1u) << "blur, mips";
            EXPECT_EQ(count(glsl, "float light0Shadow(int view, vec3 worldPos, vec3 n, vec3 positionDx, vec3 positionDy)"),
                      mips ? 1u : 0u);
        }
        const nlohmann::json moments = nlohmann::json::parse(exportSnippet(set, ExportFormat::Json))["lights"][0]["technique"]["moments"];
        EXPECT_TRUE(moments["notExported"].empty());
        EXPECT_EQ(moments["levels"], mips ? 10 : 1);
        EXPECT_EQ(moments["minFilter"], mips ? "linear-mipmap-linear" : "linear");
        EXPECT_EQ(moments.contains("mipsGlsl"), mips);
    }
}

// ShadowLab blurs a point light's moments across its cube faces' edges (moments_cube_blur.comp.glsl); the exported
// blur is the 2D one, face by face: the export names that under "Not exported" whenever it blurs a point light.
TEST(ShadowExportTechniques, APointLightsBlurAcrossCubeFacesIsNamedAsNotExported) {
    Settings s = threeLights();
    s.filter.kind = FilterKind::Vsm;
    for (const float blur : {1.0f, 5.0f}) {
        SCOPED_TRACE("blur " + std::to_string(blur));
        s.filter.blurWidth = blur;
        const ShadowExportSet set = exportSet(s);
        ASSERT_EQ(set.lights.size(), 3u);
        const nlohmann::json lights = nlohmann::json::parse(exportSnippet(set, ExportFormat::Json))["lights"];
        for (std::size_t l = 0; l < 3; ++l) {
            const nlohmann::json& notExported = lights[l]["technique"]["moments"]["notExported"];
            const bool named = notExported.size() == 1 &&
                               notExported[0].get<std::string>().find("cube faces' edges") != std::string::npos;
            EXPECT_EQ(named, l == 2 && blur > 1.0f) << "light " << l;
        }
        const std::string gl = exportSnippet(set, ExportFormat::GL);
        EXPECT_EQ(count(gl, "// Not exported: the blur across the cube faces' edges"), blur > 1.0f ? 1u : 0u);
    }
}

}  // namespace
}  // namespace shadowlab
