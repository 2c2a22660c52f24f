// The exported Vulkan rasterizer state, proven: Mesa's lavapipe renders the shadow pass of a built-in scene with the
// values parsed from `exportSnippet(..., Vulkan)`, and its depth map must match ShadowLab's GL map (llvmpipe) within
// one depth step per texel.
#include "export/export_snippets.h"
#include "gl_fixture.h"
#include "image/depth_visualization.h"
#include "light/depth_bias.h"
#include "scene/builtin_scenes.h"
#include "vulkan_depth_pass.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace shadowlab::test {
namespace {

struct MapDifference {
    double maxSteps = 0.0;        // largest |vulkan - gl| in depth steps of the format at that depth
    long overOneStep = 0;         // texels differing by more than one step
    double maxExcessSubpixels = 0.0;  // largest (|vulkan - gl| - one step) / the depth change over one subpixel
    long overBound = 0;           // texels differing by more than one step plus one subpixel's depth change
    long overCoarsestR = 0;       // texels differing by more than the format's r in [0.5, 1) (D32F: 2^-24)
    long written = 0;             // texels a caster wrote in the GL map
    std::vector<std::uint8_t> picture;  // grey: the GL map; orange: over one step; red: over the bound
};

// One depth step at `depth`: UNORM 1/(2^16 - 1); float: the spacing of floats at that depth (stricter than r,
// which is the spacing at the primitive's largest depth).
double storedStepAt(float depth, bool d16) {
    if (d16) return 1.0 / 65535.0;
    if (depth <= 0.0f) return std::ldexp(1.0, -149);
    return std::ldexp(1.0, std::ilogb(depth) - 23);
}

// The GL map's depth change per texel at i, from the smaller one-sided difference on each axis (so a silhouette
// next to the texel does not count as its slope).
double depthSlopeAt(const std::vector<float>& map, int resolution, int x, int y) {
    const std::size_t i = std::size_t(y) * std::size_t(resolution) + std::size_t(x);
    auto oneSided = [&](std::size_t before, std::size_t after) {
        return std::min(std::abs(double(map[after]) - map[i]), std::abs(double(map[i]) - map[before]));
    };
    const std::size_t row = std::size_t(resolution);
    const double sx = x > 0 && x + 1 < resolution ? oneSided(i - 1, i + 1) : 0.0;
    const double sy = y > 0 && y + 1 < resolution ? oneSided(i - row, i + row) : 0.0;
    return std::max(sx, sy);
}

// Two rasterizers may snap a vertex to different subpixels (lavapipe reports 2^-subPixelBits of a texel) and
// interpolate float depth with different rounding: besides the one-step figures, the bound allows one subpixel's
// worth of the surface's depth slope.
MapDifference compareMaps(const std::vector<float>& gl, const std::vector<float>& vk, int resolution, bool d16,
                          int subPixelBits) {
    MapDifference d;
    const std::vector<std::uint8_t> grey = depthToGray(gl, writtenDepthRange(gl));
    const double subpixel = std::ldexp(1.0, -subPixelBits);
    d.picture.resize(gl.size() * 3);
    for (int y = 0; y < resolution; ++y)
        for (int x = 0; x < resolution; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(resolution) + std::size_t(x);
            const double step = storedStepAt(std::max(gl[i], vk[i]), d16);
            const double difference = std::abs(double(vk[i]) - double(gl[i]));
            d.maxSteps = std::max(d.maxSteps, difference / step);
            const bool overStep = difference > step;
            d.overOneStep += overStep;
            d.overCoarsestR += difference > depthStepAt(d16 ? DepthFormat::D16 : DepthFormat::D32F, 0.75);
            bool overBound = false;
            if (overStep) {
                const double slopeTerm = depthSlopeAt(gl, resolution, x, y) * subpixel;
                const double excess = slopeTerm > 0.0 ? (difference - step) / slopeTerm : 1e30;
                d.maxExcessSubpixels = std::max(d.maxExcessSubpixels, excess);
                overBound = excess > 1.0;
            }
            d.overBound += overBound;
            d.written += gl[i] < 1.0f;
            d.picture[i * 3] = overStep ? 255 : grey[i];
            d.picture[i * 3 + 1] = overBound ? 0 : overStep ? 160 : grey[i];
            d.picture[i * 3 + 2] = overStep ? 0 : grey[i];
        }
    return d;
}

// ShadowLab's shadow-pass draws of `scene`, as GpuScene lays them out (vertices and indices concatenated per mesh).
DepthPassInput depthPassInput(const Scene& scene, const GpuScene& gpu) {
    DepthPassInput input;
    for (const Mesh& mesh : scene.meshes) {
        input.positions.insert(input.positions.end(), mesh.positions.begin(), mesh.positions.end());
        input.indices.insert(input.indices.end(), mesh.indices.begin(), mesh.indices.end());
    }
    for (const GpuDraw& draw : gpu.draws()) {
        const Material* material = draw.material >= 0 ? &scene.materials[std::size_t(draw.material)] : nullptr;
        EXPECT_FALSE(material && material->alphaMode == AlphaMode::Mask) << "alpha-tested casters are not in this check";
        input.draws.push_back({draw.model, std::uint32_t(draw.firstIndexByte / sizeof(std::uint32_t)), draw.baseVertex,
                               std::uint32_t(draw.indexCount), draw.mirrored, material && material->doubleSided});
    }
    return input;
}

struct Case {
    const char* scene;
    DepthFormat format;
    const char* preset;
};

void PrintTo(const Case& c, std::ostream* out) { *out << c.scene << " " << c.preset; }

class VulkanExportTest : public GlTest, public ::testing::WithParamInterface<Case> {};

TEST_P(VulkanExportTest, LavapipeMapMatchesTheGlMapWithinOneDepthStep) {
    const Case c = GetParam();
    const Scene scene = loadBuiltin(c.scene + 8);
    Settings settings = loadShippedPreset(c.preset);
    settings.lights[0].shadow.format = c.format;
    settings.lights[0].shadow.resolution = 1024;
    Renderer renderer;
    const View view = renderView(renderer, scene, settings, 64, 64);
    ASSERT_TRUE(view.stats.ok) << view.stats.error;
    const std::vector<float> glMap = renderer.shadowMap().readDepth();

    // The values a user would paste: parsed from the exported snippet, not taken from Settings.
    const std::string snippet =
        exportSnippet(makeShadowExport(settings, 0, view.stats.light, c.scene), ExportFormat::Vulkan);
    std::string parseError;
    DepthPassInput input = depthPassInput(scene, GpuScene(scene, view.stats.renderOrigin));
    input.raster = parseVulkanRaster(snippet, parseError);
    ASSERT_EQ(parseError, "") << snippet;
    input.lightViewProjection = glm::mat4(view.stats.light.viewProjection());
    input.resolution = settings.lights[0].shadow.resolution;
    const bool d16 = c.format == DepthFormat::D16;
    input.format = d16 ? VK_FORMAT_D16_UNORM : VK_FORMAT_D32_SFLOAT;
    const DepthPassResult vk = renderDepthVulkan(input);
    if (vk.noDevice) GTEST_SKIP() << "no Vulkan device (" << vk.error << "); scripts/install-deps installs lavapipe";
    ASSERT_EQ(vk.error, "");
    ASSERT_EQ(vk.depth.size(), glMap.size());

    const MapDifference d = compareMaps(glMap, vk.depth, input.resolution, d16, vk.subPixelPrecisionBits);
    const std::string name = std::string("vulkan-vs-gl-") + (c.scene + 8) + "-" + c.preset + (d16 ? "-d16" : "-d32f");
    std::filesystem::create_directories(SHADOWLAB_TEST_OUTPUT);
    writePng(std::string(SHADOWLAB_TEST_OUTPUT) + "/" + name + ".png", input.resolution, input.resolution, 3,
             d.picture.data(), true);
    std::printf("[ lavapipe ] %s on %s: max |vk - gl| = %.3g depth steps; %ld of %ld written texels (%.3f%%) over one "
                "step (%ld over r in [0.5,1)), by at most %.4f of a 1/%d-texel subpixel's depth change beyond the step; %ld "
                "over that bound\n", name.c_str(), vk.deviceName.c_str(), d.maxSteps, d.overOneStep, d.written,
                100.0 * double(d.overOneStep) / double(d.written), d.overCoarsestR, d.maxExcessSubpixels, 1 << vk.subPixelPrecisionBits,
                d.overBound);
    EXPECT_GT(d.written, long(glMap.size() / 50)) << "the casters cover the map";
    EXPECT_LE(double(d.overBound), 1e-4 * double(d.written))
        << "texels further apart than one depth step plus one subpixel's depth change; see " << name << ".png";
    if (d16) EXPECT_EQ(d.overOneStep, 0) << "D16: every texel within one depth step";
}

INSTANTIATE_TEST_SUITE_P(Exported, VulkanExportTest,
                         ::testing::Values(Case{"builtin:textbook", DepthFormat::D32F, "default"},
                                           Case{"builtin:textbook", DepthFormat::D16, "default"},
                                           Case{"builtin:grazing", DepthFormat::D32F, "acne"},
                                           Case{"builtin:grazing", DepthFormat::D16, "default"},
                                           Case{"builtin:thin-walls", DepthFormat::D32F, "peter-panning"}),
                         [](const auto& info) {
                             std::string n = std::string(info.param.scene + 8) + "_" + info.param.preset +
                                             (info.param.format == DepthFormat::D16 ? "_d16" : "_d32f");
                             std::replace(n.begin(), n.end(), '-', '_');
                             return n;
                         });

// The check can fail: the same pass without the exported bias is many steps away from ShadowLab's map.
TEST_F(GlTest, LavapipeMapWithoutTheBiasDiffersFromTheGlMap) {
    const Scene scene = loadBuiltin("textbook");
    Settings settings = loadShippedPreset("default");
    settings.lights[0].shadow.resolution = 512;
    settings.lights[0].shadow.depthBias = 2.0f;
    settings.lights[0].shadow.slopeScaledDepthBias = 2.0f;
    Renderer renderer;
    const View view = renderView(renderer, scene, settings, 64, 64);
    ASSERT_TRUE(view.stats.ok) << view.stats.error;
    DepthPassInput input = depthPassInput(scene, GpuScene(scene, view.stats.renderOrigin));
    std::string parseError;
    input.raster = parseVulkanRaster(
        exportSnippet(makeShadowExport(settings, 0, view.stats.light, "builtin:textbook"), ExportFormat::Vulkan), parseError);
    ASSERT_EQ(parseError, "");
    input.raster.depthBiasEnable = VK_FALSE;
    input.lightViewProjection = glm::mat4(view.stats.light.viewProjection());
    input.resolution = 512;
    const DepthPassResult vk = renderDepthVulkan(input);
    if (vk.noDevice) GTEST_SKIP() << "no Vulkan device (" << vk.error << ")";
    ASSERT_EQ(vk.error, "");
    const MapDifference d = compareMaps(renderer.shadowMap().readDepth(), vk.depth, 512, false, vk.subPixelPrecisionBits);
    EXPECT_GT(d.overBound, d.written / 2) << "without the bias most written texels move beyond the bound";
}

// The exporter's claim that GL's [-1,1] clip depth and Vulkan's [0,1] give the same window depth: the remapped pass
// (z' = 0.5 (z + w)) and a pass that keeps GL's clip depth (VK_EXT_depth_clip_control) write identical maps.
TEST_F(GlTest, LavapipeZeroToOneRemapMatchesGlClipDepthBitForBit) {
    const Scene scene = loadBuiltin("textbook");
    Settings settings = loadShippedPreset("default");
    settings.lights[0].shadow.resolution = 512;
    Renderer renderer;
    const View view = renderView(renderer, scene, settings, 64, 64);
    ASSERT_TRUE(view.stats.ok) << view.stats.error;
    DepthPassInput input = depthPassInput(scene, GpuScene(scene, view.stats.renderOrigin));
    std::string parseError;
    input.raster = parseVulkanRaster(
        exportSnippet(makeShadowExport(settings, 0, view.stats.light, "builtin:textbook"), ExportFormat::Vulkan), parseError);
    ASSERT_EQ(parseError, "");
    input.lightViewProjection = glm::mat4(view.stats.light.viewProjection());
    input.resolution = 512;
    const DepthPassResult remapped = renderDepthVulkan(input);
    if (remapped.noDevice) GTEST_SKIP() << "no Vulkan device (" << remapped.error << ")";
    ASSERT_EQ(remapped.error, "");
    input.glClipDepth = true;
    const DepthPassResult glClip = renderDepthVulkan(input);
    if (glClip.unsupported) GTEST_SKIP() << glClip.error;
    ASSERT_EQ(glClip.error, "");
    long different = 0;
    for (std::size_t i = 0; i < remapped.depth.size(); ++i) different += remapped.depth[i] != glClip.depth[i];
    EXPECT_EQ(different, 0);
}

}  // namespace
}  // namespace shadowlab::test
