// The export's numbers per depth format, in closed form: r, the D3D INT rounding, the Vulkan / GL values, the normal
// offset in world units, and the JSON carrying the same numbers. And the depth-format change that keeps DepthBias's
// world meaning.
#include "export/export_snippets.h"
#include "light/depth_format_change.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

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
    EXPECT_DOUBLE_EQ(makeShadowExport(withBias(DepthFormat::D16, 2), orthoLight(), "t").depthStep, 1.0 / 65535.0);
    EXPECT_DOUBLE_EQ(makeShadowExport(withBias(DepthFormat::D24, 2), orthoLight(), "t").depthStep, 1.0 / 16777215.0);
    EXPECT_DOUBLE_EQ(makeShadowExport(withBias(DepthFormat::D32F, 2), orthoLight(), "t").depthStep, std::ldexp(1.0, -24));
}

TEST(ShadowExport, D16SnippetsCarryTheFormatsNumbers) {
    const ShadowExport e = makeShadowExport(withBias(DepthFormat::D16, 1.5f), orthoLight(), "builtin:test");
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
    const std::string d24 = exportSnippet(makeShadowExport(withBias(DepthFormat::D24, 3), orthoLight(), "t"),
                                          ExportFormat::D3D11);
    EXPECT_TRUE(contains(d24, "DXGI_FORMAT_D24_UNORM_S8_UINT")) << d24;
    EXPECT_TRUE(contains(d24, "r = 1/(2^24 - 1) = 5.96046e-08"));
    EXPECT_TRUE(contains(d24, "shadowRaster.DepthBias = 3;"));
    EXPECT_FALSE(contains(d24, "is an INT here")) << "an integral DepthBias needs no note";
    const std::string d32 = exportSnippet(makeShadowExport(withBias(DepthFormat::D32F, 2), orthoLight(), "t"),
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
    const ShadowExport e = makeShadowExport(s, orthoLight(), "builtin:test");
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
    const ShadowExport e = makeShadowExport(s, light, "t");
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
    const std::string normal = exportSnippet(makeShadowExport(withBias(DepthFormat::D24, 3), orthoLight(), "t"),
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

}  // namespace
}  // namespace shadowlab
