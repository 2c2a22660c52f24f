// The exported Vulkan rasterizer state, proven: Mesa's lavapipe renders the shadow pass of a built-in scene with the
// values parsed from `exportSnippet(..., Vulkan)`, and its depth map must match ShadowLab's GL map (llvmpipe) within
// one depth step per texel plus that texel's rounding bound (raster_rounding_bound.h), computed from the geometry.
#include "export/export_snippets.h"
#include "scene/scene.h"
#include "gl_fixture.h"
#include "image/depth_visualization.h"
#include "light/depth_bias.h"
#include "scene/builtin_scenes.h"
#include "raster_rounding_bound.h"
#include "vulkan_depth_pass.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <random>

namespace shadowlab::test {
namespace {

// One depth step at `depth`: UNORM 1/(2^16 - 1); float: the spacing of floats at that depth (stricter than r,
// which is the spacing at the primitive's largest depth).
double storedStepAt(float depth, bool d16) {
    if (d16) return 1.0 / 65535.0;
    if (depth <= 0.0f) return std::ldexp(1.0, -149);
    return std::ldexp(1.0, std::ilogb(depth) - 23);
}

// Beyond one step of the format, each written texel may differ by its rounding bound (raster_rounding_bound.h: the two
// rasterizers' vertex snapping and float rounding, magnified on thin triangles by the slope term); a texel without a
// bound counts as over it when it differs by more than a step.
struct MapDifference {
    long written = 0, overStep = 0, overBound = 0, unbounded = 0;
    double maxSteps = 0.0, maxExcessSteps = 0.0, maxBoundSteps = 0.0, medianBoundSteps = 0.0;
    std::vector<std::uint8_t> picture;  // grey: the GL map; orange: over one step; red: over the bound
};

MapDifference compareMaps(const std::vector<float>& gl, const std::vector<float>& vk, const RoundingBound& bound,
                          bool d16, bool reversedZ = false) {
    MapDifference d;
    const std::vector<std::uint8_t> grey = depthToGray(gl, writtenDepthRange(gl));
    d.picture.resize(gl.size() * 3);
    std::vector<double> boundSteps;
    for (std::size_t i = 0; i < gl.size(); ++i) {
        const bool written = reversedZ ? gl[i] > 0.0f : gl[i] < 1.0f;
        const double step = storedStepAt(std::max(gl[i], vk[i]), d16);
        const double difference = std::abs(double(vk[i]) - double(gl[i]));
        bool over = false;
        if (written) {
            ++d.written;
            d.maxSteps = std::max(d.maxSteps, difference / step);
            d.overStep += difference > step;
            if (bound.depth[i] < 0.0) {
                ++d.unbounded;
                over = difference > step;
            } else {
                d.maxBoundSteps = std::max(d.maxBoundSteps, bound.depth[i] / step);
                boundSteps.push_back(bound.depth[i] / step);
                d.maxExcessSteps = std::max(d.maxExcessSteps, (difference - step - bound.depth[i]) / step);
                over = difference > step + bound.depth[i];
            }
            d.overBound += over;
        }
        const bool overStep = difference > step;
        d.picture[i * 3] = overStep ? 255 : grey[i];
        d.picture[i * 3 + 1] = over ? 0 : overStep ? 160 : grey[i];
        d.picture[i * 3 + 2] = overStep ? 0 : grey[i];
    }
    if (!boundSteps.empty()) {
        std::nth_element(boundSteps.begin(), boundSteps.begin() + std::ptrdiff_t(boundSteps.size() / 2), boundSteps.end());
        d.medianBoundSteps = boundSteps[boundSteps.size() / 2];
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

    const RoundingBound bound = rasterRoundingBound(input, glMap, vk.subPixelPrecisionBits);
    const MapDifference d = compareMaps(glMap, vk.depth, bound, d16);
    const std::string name = std::string("vulkan-vs-gl-") + (c.scene + 8) + "-" + c.preset + (d16 ? "-d16" : "-d32f");
    std::filesystem::create_directories(SHADOWLAB_TEST_OUTPUT);
    writePng(std::string(SHADOWLAB_TEST_OUTPUT) + "/" + name + ".png", input.resolution, input.resolution, 3,
             d.picture.data(), true);
    std::printf("[ lavapipe ] %s on %s: max |vk - gl| = %.3g depth steps; %ld of %ld written texels (%.3f%%) over one "
                "step; %ld over one step + their rounding bound (largest bound %.3g steps, %ld texels unbounded)\n",
                name.c_str(), vk.deviceName.c_str(), d.maxSteps, d.overStep, d.written,
                100.0 * double(d.overStep) / double(d.written), d.overBound, d.maxBoundSteps, d.unbounded);
    EXPECT_GT(d.written, long(glMap.size() / 50)) << "the casters cover the map";
    EXPECT_LE(double(d.overBound), 1e-4 * double(d.written))
        << "texels further apart than one depth step plus their rounding bound; see " << name << ".png";
    if (d16) EXPECT_EQ(d.overStep, 0) << "D16: every texel within one depth step";
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

// ---- The property test: random presets, each exported and rendered by lavapipe from the snippet alone ----
//
// Each preset (one light) is drawn from a seeded RNG: scene (textbook / grazing), light type (directional / spot),
// resolution 64..256, format (D16 / D32F; D24 is not renderable by this check's Vulkan pass), reversed-Z, cull mode,
// DepthBias 0..8, SlopeScaledDepthBias 0..4, DepthBiasClamp (0 or 1e-4..5e-3), depth clamp, filter and receiver-plane
// bias (these two do not change the map; they are exported too). ShadowLab renders it (GL, llvmpipe); the export's
// Vulkan snippet is parsed for EVERYTHING the Vulkan pass takes: the rasterizer state, the depth test and clear
// (reversed-Z), the format and the light's matrix (its [0,1] clip depth used as is). Lavapipe renders that.
// Tolerance (the one the fixed cases above state): no texel further from the GL map than one depth step of the
// format plus its rounding bound (raster_rounding_bound.h: what the two rasterizers' vertex snapping to
// 1/2^subPixelPrecisionBits of a texel and their float vertex arithmetic may move it, the slope factor times the
// triangle's gradient change included), for at most max(1, 1e-4 x the written texels) texels (a 64^2 map may differ
// at one silhouette texel, where the two cover it differently). The fixed cases' stricter D16 rule (every texel within
// one step) does not hold here: the exported matrix is remapped to [0,1] on the CPU in double, the fixed cases remap
// on the GPU in float, and 1-2 texels of 65536 differ by 1.004 steps.
// The shadow factor S is a function of the map, the sampler and the shader code; the maps agreeing within the
// tolerance is what this test proves (the sampler / filter text is checked by the unit tests). A failing preset
// prints its seed; SHADOWLAB_EXPORT_SEED=<seed> SHADOWLAB_EXPORT_PRESETS=1 reruns it alone.

struct RandomPreset {
    std::string scene;  // "textbook"
    Settings settings;
    std::string summary;
};

RandomPreset randomPreset(std::uint32_t seed) {
    std::mt19937 rng(seed);
    const auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    RandomPreset p;
    p.scene = pick(2) ? "grazing" : "textbook";
    p.settings = loadShippedPreset("default");
    LightSettings& l = p.settings.lights[0];
    l.type = pick(2) ? LightType::Spot : LightType::Directional;
    if (l.type == LightType::Directional) {
        l.direction = {float(uniform(-0.8, 0.8)), -1.0f, float(uniform(-0.8, 0.8))};
    } else {
        l.position = {float(uniform(-4.0, 4.0)), float(uniform(5.0, 9.0)), float(uniform(-4.0, 4.0))};
        l.direction = glm::vec3(float(uniform(-0.3, 0.3)), 0.0f, float(uniform(-0.3, 0.3))) - l.position;  // at the scene
        l.spotConeDeg = float(uniform(50.0, 100.0));
    }
    static const int resolutions[] = {64, 96, 128, 192, 256};
    l.shadow.resolution = resolutions[pick(5)];
    l.shadow.format = pick(2) ? DepthFormat::D16 : DepthFormat::D32F;
    l.shadow.reversedZ = pick(2) == 1;
    static const CullMode culls[] = {CullMode::Back, CullMode::Front, CullMode::None};
    l.shadow.cullMode = culls[pick(3)];
    l.shadow.depthBias = pick(4) == 0 ? 0.0f : float(uniform(0.0, 8.0));
    l.shadow.slopeScaledDepthBias = pick(4) == 0 ? 0.0f : float(uniform(0.0, 4.0));
    l.shadow.depthBiasClamp = pick(2) ? 0.0f : float(uniform(1e-4, 5e-3));
    l.shadow.receiverPlaneBias = pick(2) == 1;
    l.projection.depthClamp = pick(2) == 1;
    static const FilterKind filters[] = {FilterKind::Point, FilterKind::Hardware2x2, FilterKind::Pcf, FilterKind::Poisson};
    p.settings.filter.kind = filters[pick(4)];
    char text[256];
    std::snprintf(text, sizeof text, "%s %s %d %s%s cull %d bias %.3g slope %.3g clamp %.3g depthClamp %d", p.scene.c_str(),
                  l.type == LightType::Spot ? "spot" : "directional", l.shadow.resolution,
                  l.shadow.format == DepthFormat::D16 ? "d16" : "d32f", l.shadow.reversedZ ? " reversedZ" : "",
                  int(l.shadow.cullMode), double(l.shadow.depthBias), double(l.shadow.slopeScaledDepthBias),
                  double(l.shadow.depthBiasClamp), int(l.projection.depthClamp));
    p.summary = text;
    return p;
}

std::uint32_t envNumber(const char* name, std::uint32_t fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::uint32_t(std::strtoul(v, nullptr, 10)) : fallback;
}

// Seed 19028 (textbook, spot, 96^2, D32F, SlopeScaledDepthBias 2.67) differs on 1,147 of 8,390 texels by up to 53
// steps, all within their rounding bound: llvmpipe and lavapipe round a triangle's corners differently, and on sliver
// triangles at the sphere's outline the slope term magnifies that (a constant "one subpixel of depth slope" left 247
// texels over). Breaking the export fails it: no slope factor, the slope factor 5 % off or no constant bias.
TEST_F(GlTest, RandomPresetsExportedToVulkanRenderShadowLabsMapOnLavapipe) {
    const std::uint32_t firstSeed = envNumber("SHADOWLAB_EXPORT_SEED", 19001);
    const std::uint32_t presets = envNumber("SHADOWLAB_EXPORT_PRESETS", 32);
    const auto start = std::chrono::steady_clock::now();
    Renderer renderer;
    long texels = 0, overStep = 0, overBound = 0, unbounded = 0;
    double maxSteps = 0.0, maxBoundSteps = 0.0;
    std::vector<double> medians;
    std::uint32_t checked = 0;
    for (std::uint32_t seed = firstSeed; seed < firstSeed + presets; ++seed) {
        const RandomPreset p = randomPreset(seed);
        const std::string where = "seed " + std::to_string(seed) + " (" + p.summary + ")";
        SCOPED_TRACE(where);
        const Scene scene = loadBuiltin(p.scene.c_str());
        const View view = renderView(renderer, scene, p.settings, 32, 32);
        ASSERT_TRUE(view.stats.ok) << view.stats.error;
        const std::vector<float> glMap = renderer.shadowMap().readDepth();

        std::string error;
        const std::optional<ShadowExportSet> set = exportForScene(p.settings, scene, "builtin:" + p.scene, 0, error);
        ASSERT_TRUE(set && set->lights.size() == 1 && set->lights[0].shadow) << error;
        const ShadowExport& e = *set->lights[0].shadow;
        const std::string snippet = exportSnippet(e, ExportFormat::Vulkan);
        DepthPassInput input = depthPassInput(scene, GpuScene(scene, e.renderOrigin));
        input.raster = parseVulkanRaster(snippet, error);
        ASSERT_EQ(error, "") << snippet;
        const VulkanPassState state = parseVulkanPassState(snippet, "light0ViewProjection", error);
        ASSERT_EQ(error, "") << snippet;
        input.lightViewProjection = state.viewProjection;
        input.matrixZeroToOne = true;
        input.reversedZ = state.reversedZ;
        input.resolution = p.settings.lights[0].shadow.resolution;
        ASSERT_TRUE(snippet.find("Shadow map: " + std::to_string(input.resolution) + "x" +
                                 std::to_string(input.resolution)) != std::string::npos);
        const bool d16 = snippet.find("VK_FORMAT_D16_UNORM") != std::string::npos;
        ASSERT_NE(d16, snippet.find("VK_FORMAT_D32_SFLOAT") != std::string::npos) << "exactly one format";
        input.format = d16 ? VK_FORMAT_D16_UNORM : VK_FORMAT_D32_SFLOAT;
        const DepthPassResult vk = renderDepthVulkan(input);
        if (vk.noDevice) GTEST_SKIP() << "no Vulkan device (" << vk.error << "); scripts/install-deps installs lavapipe";
        ASSERT_EQ(vk.error, "");
        ASSERT_EQ(vk.depth.size(), glMap.size());

        const RoundingBound bound = rasterRoundingBound(input, glMap, vk.subPixelPrecisionBits);
        const MapDifference d = compareMaps(glMap, vk.depth, bound, d16, state.reversedZ);
        EXPECT_GT(d.written, 0) << "some caster is in the map (culling may leave few)";
        const bool ok = double(d.overBound) <= std::max(1.0, 1e-4 * double(d.written));
        if (!ok) {
            const std::string name = "vulkan-property-seed-" + std::to_string(seed);
            std::filesystem::create_directories(SHADOWLAB_TEST_OUTPUT);
            writePng(std::string(SHADOWLAB_TEST_OUTPUT) + "/" + name + ".png", input.resolution, input.resolution, 3,
                     d.picture.data(), true);
            ADD_FAILURE() << "FAILING PRESET " << where << ": " << d.overBound << " of " << d.written
                          << " written texels beyond one step + their rounding bound (" << d.overStep
                          << " beyond one step, max " << d.maxSteps << " steps; " << bound.undetermined
                          << " texels of triangles thinner than the grid, " << bound.uncovered
                          << " no triangle covers); picture " << name
                          << ".png; rerun: SHADOWLAB_EXPORT_SEED=" << seed << " SHADOWLAB_EXPORT_PRESETS=1";
        }
        texels += d.written;
        overStep += d.overStep;
        overBound += d.overBound;
        unbounded += d.unbounded;
        maxSteps = std::max(maxSteps, d.maxSteps);
        maxBoundSteps = std::max(maxBoundSteps, d.maxBoundSteps);
        medians.push_back(d.medianBoundSteps);
        ++checked;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::sort(medians.begin(), medians.end());
    std::printf("[ lavapipe ] property: %u random presets (seeds %u..%u), %ld written texels compared, %.1f s: %ld over one "
                "step (max %.3g steps), %ld over one step + their rounding bound, %ld without a bound; the bound's median "
                "per preset at most %.3g steps, its largest %.3g steps\n",
                checked, firstSeed, firstSeed + presets - 1, texels, seconds, overStep, maxSteps, overBound, unbounded,
                medians.empty() ? 0.0 : medians.back(), maxBoundSteps);
    EXPECT_EQ(checked, presets);
}

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
    input.lightViewProjection = glm::mat4(view.stats.light.viewProjection());
    input.resolution = 512;
    const DepthPassInput exported = input;  // the bound is the exported state's
    input.raster.depthBiasEnable = VK_FALSE;
    const DepthPassResult vk = renderDepthVulkan(input);
    if (vk.noDevice) GTEST_SKIP() << "no Vulkan device (" << vk.error << ")";
    ASSERT_EQ(vk.error, "");
    const std::vector<float> glMap = renderer.shadowMap().readDepth();
    const MapDifference d =
        compareMaps(glMap, vk.depth, rasterRoundingBound(exported, glMap, vk.subPixelPrecisionBits), false);
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
