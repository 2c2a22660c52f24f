// Moments techniques (VSM, EVSM2/4, MSM) and PCSS exported: the snippet carries ShadowLab's own lookup GLSL
// (shaders/shadow/lookup.glsl with the technique's file), its moments and blur compute shaders
// (shaders/moments.comp.glsl) and their numbers. Checked here: every exported shader compiles with glslangValidator,
// as Vulkan SPIR-V (its descriptors bound) and as OpenGL GLSL, for each technique, precision and light kind; and the
// exported GL compute shaders, run on ShadowLab's own depth map with the exported blur radius and weights, store
// exactly the moments ShadowLab's moments pass stores. (The lookup's S against ShadowLab's main pass:
// tests/accuracy/test_export_techniques.cpp, which has the pixel probe.)
#include "export/export_snippets.h"
#include "export/shadow_shader_code.h"
#include "gl/gl.h"
#include "gl/gl_objects.h"
#include "gl/program.h"
#include "gl_fixture.h"
#include "scene/builtin_scenes.h"
#include "settings/settings_fields.h"
#include "shading/filters/filter_technique.h"
#include "shadow/moments_pass.h"
#include "vulkan_lookup_pass.h"

#include <glm/gtc/packing.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace shadowlab::test {
namespace {

// glslangValidator on `text` as a shader of `stage` ("frag", "comp"): Vulkan SPIR-V (-V) or OpenGL GLSL. "" or its log.
std::string glslang(const std::string& text, const std::string& stage, bool vulkan, const std::string& name) {
    const std::filesystem::path folder = std::filesystem::path(SHADOWLAB_TEST_OUTPUT) / "export-glsl";
    std::filesystem::create_directories(folder);
    const std::filesystem::path file = folder / (name + (vulkan ? "-vk." : "-gl.") + stage);
    std::ofstream(file) << text;
    const std::string command = std::string("glslangValidator ") + (vulkan ? "-V -o /dev/null " : "") + "'" +
                                file.string() + "' 2>&1";
    std::string log;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return "could not run glslangValidator";
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) log += buffer;
    const int status = pclose(pipe);
    return status == 0 ? "" : file.string() + ":\n" + log;
}

// The exported lookup in a fragment shader, as a user would call it.
std::string lookupFragment(const ShadowExport& e, const std::string& lookup) {
    const std::string p = "light" + std::to_string(e.lightIndex);
    const std::string args = std::string(e.lightType == LightType::Point ? "" : "0, ") + "vWorld, normalize(vNormal)" +
                             (e.receiverPlane ? ", dFdx(vWorld), dFdy(vWorld)" : "");
    return "#version 450 core\n" + lookup +
           "layout(location = 0) in vec3 vWorld;\nlayout(location = 1) in vec3 vNormal;\n"
           "layout(location = 0) out vec4 outColor;\n"
           "void main() { outColor = vec4(vec3(" + p + "Shadow(" + args + ")), 1.0); }\n";
}

struct TechniqueCase {
    FilterKind kind;
    int bits;
    LightType light;
    bool cascaded;
    bool receiverPlane;
};

Settings caseSettings(const TechniqueCase& c) {
    Settings s = loadShippedPreset("default");
    s.filter.kind = c.kind;
    s.filter.momentBits = c.bits;
    s.filter.blurWidth = 5.0f;
    LightSettings& l = s.lights[0];
    l.type = c.light;
    l.position = {2.0f, 7.0f, 3.0f};
    l.direction = {-0.3f, -1.0f, -0.4f};
    l.size = c.light == LightType::Directional ? 2.0f : 0.2f;
    l.shadow.resolution = 128;
    l.shadow.receiverPlaneBias = c.receiverPlane;
    if (c.cascaded) {
        l.projection.fit = ProjectionFit::Cascades;
        l.projection.cascadeCount = 3;
        l.projection.shadowDistance = 30.0f;
    }
    return s;
}

std::string caseName(const TechniqueCase& c) {
    return std::string(filterTechnique(c.kind).name) + "-" + std::to_string(c.bits) + "-" + lightTypeName(c.light) +
           (c.cascaded ? "-cascades" : "") + (c.receiverPlane ? "-plane" : "");
}

}  // namespace

// Before this export, moments techniques and PCSS were refused (no snippet at all).
TEST(ExportTechniquesGlsl, EveryExportedShaderCompilesForVulkanAndOpenGl) {
    std::vector<TechniqueCase> cases;
    for (FilterKind kind : {FilterKind::Vsm, FilterKind::Evsm2, FilterKind::Evsm4, FilterKind::Msm})
        for (int bits : {16, 32}) cases.push_back({kind, bits, LightType::Directional, false, false});
    for (FilterKind kind : {FilterKind::Vsm, FilterKind::Pcss}) {
        cases.push_back({kind, 32, LightType::Spot, false, kind == FilterKind::Pcss});
        cases.push_back({kind, 32, LightType::Point, false, false});
        cases.push_back({kind, 32, LightType::Directional, true, false});
    }
    cases.push_back({FilterKind::Pcss, 32, LightType::Directional, false, true});
    const Scene scene = loadBuiltin("textbook");
    ViewCamera camera;  // for the cascades: near the floor looking across it, render-origin-relative
    camera.eye = glm::dvec3(-4.0, 1.2, 9.0) - renderOriginOf(scene.bounds);
    camera.forward = glm::normalize(glm::dvec3(5.0, -0.9, -12.0));
    camera.right = glm::normalize(glm::cross(camera.forward, glm::dvec3(0.0, 1.0, 0.0)));
    camera.up = glm::cross(camera.right, camera.forward);
    camera.aspect = 16.0 / 9.0;
    camera.farPlane = 100.0;
    int compiled = 0;
    for (const TechniqueCase& c : cases) {
        const std::string name = caseName(c);
        SCOPED_TRACE(name);
        std::string error;
        const std::optional<ShadowExportSet> set =
            exportForScene(caseSettings(c), scene, "builtin:textbook", 0, error, &camera);
        ASSERT_TRUE(set && set->lights.at(0).shadow) << error;
        const ShadowExport& e = *set->lights[0].shadow;
        EXPECT_EQ(e.receiverPlane, c.receiverPlane);
        // OpenGL's flavour runs in GL on a directional light (the moments passes below, the lookup in
        // tests/accuracy/test_export_techniques.cpp); here it is compiled for the other light kinds.
        const bool glToo = c.light != LightType::Directional || c.cascaded;
        for (const bool vulkan : {true, false}) {
            if (!vulkan && !glToo) continue;
            std::vector<VulkanBinding> bindings;
            const std::string lookup = techniqueLookupCode(e, vulkan, &bindings);
            // The snippet carries that text (and the moments passes) as is.
            const std::string snippet = exportSnippet(e, vulkan ? ExportFormat::Vulkan : ExportFormat::GL);
            EXPECT_NE(snippet.find(lookup), std::string::npos) << "the snippet holds the lookup";
            EXPECT_EQ(lookup.find("\n#include"), std::string::npos) << "every #include expanded";
            EXPECT_EQ(glslang(lookupFragment(e, lookup), "frag", vulkan, name + "-lookup"), "");
            ++compiled;
            if (vulkan) {
                for (const VulkanBinding& b : bindings)
                    EXPECT_FALSE(b.block) << b.name << ": every value of the lookup is baked in, only maps are bound";
                EXPECT_NE(lookup.find(e.momentTechnique ? "(the moments)" : "(the depth map, comparison sampler)"),
                          std::string::npos) << "the lookup names the descriptors it reads";
            }
            if (!e.momentTechnique) continue;
            const MomentsPassShaders passes = momentsPassShaders(e, vulkan);
            EXPECT_NE(snippet.find(passes.convert), std::string::npos);
            EXPECT_NE(snippet.find(passes.blur), std::string::npos);
            EXPECT_EQ(glslang(passes.convert, "comp", vulkan, name + "-convert"), "");
            EXPECT_EQ(glslang(passes.blur, "comp", vulkan, name + "-blur"), "");
            compiled += 2;
        }
        // D3D: the same GLSL, commented, beside its pipeline state (no HLSL translation).
        EXPECT_NE(exportSnippet(e, ExportFormat::D3D12).find("ShadowLab's lookup is GLSL; translate it"), std::string::npos);
        const nlohmann::json json = nlohmann::json::parse(exportSnippet(e, ExportFormat::Json));
        EXPECT_EQ(json["technique"]["lookupGlsl"], techniqueLookupCode(e, false));
    }
    std::printf("[ glslang ] %zu exported setups, %d shaders compiled (Vulkan SPIR-V and OpenGL GLSL)\n", cases.size(),
                compiled);
}

// The exported GL moments passes, run on ShadowLab's depth map with the exported numbers alone (from the JSON
// export: the two shaders, the format, each view's radius and weights), store what ShadowLab's moments pass stores,
// bit for bit: they are its shader files, not a copy.
TEST_F(GlTest, ExportedMomentsPassesStoreShadowLabsMomentsBitForBit) {
    struct Format { const char* name; GLenum format; };
    const Format formats[] = {{"GL_RG16F", GL_RG16F}, {"GL_RG32F", GL_RG32F}, {"GL_RGBA16F", GL_RGBA16F},
                              {"GL_RGBA32F", GL_RGBA32F}, {"GL_RGBA16", GL_RGBA16}};
    const Scene scene = loadBuiltin("textbook");
    Renderer renderer;
    struct Case { FilterKind kind; int bits; float blur; };
    for (const Case& c : {Case{FilterKind::Vsm, 32, 5.0f}, Case{FilterKind::Evsm4, 16, 4.5f}, Case{FilterKind::Msm, 16, 7.0f},
                          Case{FilterKind::Msm, 32, 1.0f}}) {
        Settings s = loadShippedPreset("default");
        s.filter.kind = c.kind;
        s.filter.momentBits = c.bits;
        s.filter.blurWidth = c.blur;
        s.filter.positiveExponent = 40.0f;  // clamped at 16 bits
        const int resolution = s.lights[0].shadow.resolution = 128;
        const std::string name = std::string(filterTechnique(c.kind).name) + "-" + std::to_string(c.bits);
        SCOPED_TRACE(name);
        const View view = renderView(renderer, scene, s, 32, 32);
        ASSERT_TRUE(view.stats.ok) << view.stats.error;
        const std::vector<glm::vec4> expected = renderer.viewMoments({0, ShadowViewKind::Single, 0}, 0, 0, resolution, resolution);
        ASSERT_EQ(expected.size(), std::size_t(resolution * resolution));
        const std::vector<float> depth = renderer.shadowMap().readDepth();

        std::string error;
        const std::optional<ShadowExportSet> set = exportForScene(s, scene, "builtin:textbook", 0, error);
        ASSERT_TRUE(set && set->lights.at(0).shadow) << error;
        const nlohmann::json technique = nlohmann::json::parse(exportSnippet(*set->lights[0].shadow, ExportFormat::Json))["technique"];
        const nlohmann::json& moments = technique["moments"];
        GLenum format = 0;
        for (const Format& f : formats)
            if (moments["glFormat"] == f.name) format = f.format;
        ASSERT_EQ(format, momentInternalFormat(filterTechnique(c.kind), c.bits)) << moments["glFormat"];
        if (c.bits == 16 && c.kind == FilterKind::Evsm4)
            EXPECT_FALSE(moments["clamps"].empty()) << "the exponent 40 is clamped at 16 bits, and the export says so";

        // The depth map as the convert pass reads it: a 2D array of one layer.
        gl::Texture depthArray = gl::createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(depthArray.id(), 1, GL_DEPTH_COMPONENT32F, resolution, resolution, 1);
        glTextureSubImage3D(depthArray.id(), 0, 0, 0, 0, resolution, resolution, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
        glTextureParameteri(depthArray.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(depthArray.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl::Texture out = gl::createTexture(GL_TEXTURE_2D_ARRAY), scratch = gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage3D(out.id(), 1, format, resolution, resolution, 1);
        glTextureStorage2D(scratch.id(), 1, format, resolution, resolution);
        const gl::Program convert = gl::buildProgram({{GL_COMPUTE_SHADER, "exported convert", moments["convertGlsl"]}}, {});
        const gl::Program blur = gl::buildProgram({{GL_COMPUTE_SHADER, "exported blur", moments["blurGlsl"]}}, {});
        const GLuint groups = GLuint((resolution + 7) / 8);
        glUseProgram(convert.id());
        glUniform1i(glGetUniformLocation(convert.id(), "uLayer"), 0);
        glUniform1i(glGetUniformLocation(convert.id(), "uDepth"), 0);
        glBindTextureUnit(0, depthArray.id());
        glBindSampler(0, 0);
        glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
        glDispatchCompute(groups, groups, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        const nlohmann::json& viewBlur = moments["blur"].at(0);
        const int radius = viewBlur["radius"];
        if (radius > 0) {
            const std::vector<float> weights = viewBlur["weights"];
            glUseProgram(blur.id());
            glUniform1i(glGetUniformLocation(blur.id(), "uRadius"), radius);
            glUniform1fv(glGetUniformLocation(blur.id(), "uWeights"), GLsizei(weights.size()), weights.data());
            glBindImageTexture(1, out.id(), 0, GL_FALSE, 0, GL_READ_ONLY, format);
            glBindImageTexture(0, scratch.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
            glUniform2i(glGetUniformLocation(blur.id(), "uDirection"), 1, 0);
            glDispatchCompute(groups, groups, 1);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            glBindImageTexture(1, scratch.id(), 0, GL_FALSE, 0, GL_READ_ONLY, format);
            glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
            glUniform2i(glGetUniformLocation(blur.id(), "uDirection"), 0, 1);
            glDispatchCompute(groups, groups, 1);
        }
        glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
        std::vector<glm::vec4> got(expected.size());
        glGetTextureImage(out.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(got.size() * sizeof(glm::vec4)), got.data());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < got.size(); ++i) differing += got[i] != expected[i];
        EXPECT_EQ(differing, 0u) << "texels whose exported moments differ from ShadowLab's";
        std::printf("[ export ] %s: the exported moments passes (%s, blur radius %d) equal ShadowLab's at %zu of %zu "
                    "texels\n", name.c_str(), moments["glFormat"].get<std::string>().c_str(), radius,
                    got.size() - differing, got.size());
    }
}

// The wrapper both runs below put around the exported lookup: S of each point (world position, then normal).
std::string lookupCompute(const std::string& lookup, bool vulkan) {
    const std::string set = vulkan ? "set = 0, " : "";
    return "#version 450 core\nlayout(local_size_x = 64) in;\n" + lookup + "layout(std430, " + set +
           "binding = 10) readonly buffer Points { vec4 points[]; };\nlayout(std430, " + set +
           "binding = 11) writeonly buffer Shadows { float shadows[]; };\n"
           "void main() {\n    uint i = gl_GlobalInvocationID.x;\n    if (i >= uint(points.length() / 2)) return;\n"
           "    shadows[i] = light0Shadow(0, points[2u * i].xyz, normalize(points[2u * i + 1u].xyz));\n}\n";
}

// The exported Vulkan lookup of each moments technique, run by lavapipe on ShadowLab's stored moments (in the exported
// format, sampler and border, at the exported binding), gives the S the exported GL lookup gives in GL at the same
// surface points (a grid over the textbook's floor), which tests/accuracy/test_export_techniques.cpp ties to
// ShadowLab's main pass. PCSS hashes gl_FragCoord: a compute shader cannot run it (compiled only, above).
TEST_F(GlTest, ExportedMomentsLookupOnLavapipeGivesTheShadowGlGives) {
    struct Format { const char* name; VkFormat vk; int channels; int bytes; bool unorm; };
    const Format formats[] = {{"rg16f", VK_FORMAT_R16G16_SFLOAT, 2, 2, false}, {"rg32f", VK_FORMAT_R32G32_SFLOAT, 2, 4, false},
                              {"rgba16f", VK_FORMAT_R16G16B16A16_SFLOAT, 4, 2, false},
                              {"rgba32f", VK_FORMAT_R32G32B32A32_SFLOAT, 4, 4, false},
                              {"rgba16", VK_FORMAT_R16G16B16A16_UNORM, 4, 2, true}};
    const Scene scene = loadBuiltin("textbook");
    Renderer renderer;
    struct Case { FilterKind kind; int bits; };
    for (const Case& c : {Case{FilterKind::Vsm, 32}, Case{FilterKind::Evsm2, 16}, Case{FilterKind::Evsm4, 32},
                          Case{FilterKind::Msm, 16}, Case{FilterKind::Msm, 32}}) {
        Settings s = loadShippedPreset("default");
        s.filter.kind = c.kind;
        s.filter.momentBits = c.bits;
        s.filter.blurWidth = 5.0f;
        s.filter.bleedReduction = 0.2f;
        const int resolution = s.lights[0].shadow.resolution = 256;
        const std::string name = std::string(filterTechnique(c.kind).name) + "-" + std::to_string(c.bits);
        SCOPED_TRACE(name);
        const View view = renderView(renderer, scene, s, 32, 32);
        ASSERT_TRUE(view.stats.ok) << view.stats.error;
        const std::vector<glm::vec4> stored = renderer.viewMoments({0, ShadowViewKind::Single, 0}, 0, 0, resolution, resolution);
        ASSERT_EQ(stored.size(), std::size_t(resolution * resolution));
        std::string error;
        const std::optional<ShadowExportSet> set = exportForScene(s, scene, "builtin:textbook", 0, error);
        ASSERT_TRUE(set && set->lights.at(0).shadow) << error;
        const ShadowExport& e = *set->lights[0].shadow;
        const nlohmann::json json = nlohmann::json::parse(exportSnippet(e, ExportFormat::Json));
        const nlohmann::json& moments = json["technique"]["moments"];
        const Format* format = nullptr;
        for (const Format& f : formats)
            if (moments["format"] == f.name) format = &f;
        ASSERT_NE(format, nullptr) << moments["format"];

        // Surface points: a 64 x 64 grid over the floor (its top, the scene's lowest y), normal up.
        std::vector<glm::vec4> points;
        const glm::dvec3 lo = scene.bounds.min, hi = scene.bounds.max;
        for (int j = 0; j < 64; ++j)
            for (int i = 0; i < 64; ++i) {
                const glm::dvec3 p(lo.x + (hi.x - lo.x) * (i + 0.5) / 64.0, lo.y, lo.z + (hi.z - lo.z) * (j + 0.5) / 64.0);
                points.push_back(glm::vec4(glm::vec3(p - e.renderOrigin), 1.0f));
                points.push_back(glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
            }
        const std::size_t count = points.size() / 2;

        // GL: the exported GL lookup on the same moments, through the exported sampler.
        const GLenum glFormat = momentInternalFormat(filterTechnique(c.kind), c.bits);
        gl::Texture map = gl::createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(map.id(), 1, glFormat, resolution, resolution, 1);
        glTextureSubImage3D(map.id(), 0, 0, 0, 0, resolution, resolution, 1, GL_RGBA, GL_FLOAT, stored.data());
        const std::vector<float> border = moments["border"];
        const std::string address = json["sampler"]["addressMode"];
        const GLint wrap = address == "wrap" ? GL_REPEAT : address == "clamp" ? GL_CLAMP_TO_EDGE : GL_CLAMP_TO_BORDER;
        gl::Sampler sampler = gl::createSampler();
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_S, wrap);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, wrap);
        glSamplerParameterfv(sampler.id(), GL_TEXTURE_BORDER_COLOR, border.data());
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        const gl::Program program = gl::buildProgram(
            {{GL_COMPUTE_SHADER, "exported lookup (GL)", lookupCompute(json["technique"]["lookupGlsl"], false)}}, {});
        gl::Buffer pointBuffer = gl::createBuffer(), shadowBuffer = gl::createBuffer();
        glNamedBufferData(pointBuffer.id(), GLsizeiptr(points.size() * sizeof(glm::vec4)), points.data(), GL_STATIC_DRAW);
        glNamedBufferData(shadowBuffer.id(), GLsizeiptr(count * sizeof(float)), nullptr, GL_STATIC_READ);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, pointBuffer.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 11, shadowBuffer.id());
        glUseProgram(program.id());
        glUniform1i(glGetUniformLocation(program.id(), "uMaps2D[0]"), 0);
        glBindTextureUnit(0, map.id());
        glBindSampler(0, sampler.id());
        glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<float> glShadow(count);
        glGetNamedBufferSubData(shadowBuffer.id(), 0, GLsizeiptr(count * sizeof(float)), glShadow.data());
        glBindSampler(0, 0);

        // Vulkan: the exported Vulkan lookup, the map at the binding the export names.
        std::vector<VulkanBinding> bindings;
        const std::string lookup = techniqueLookupCode(e, true, &bindings);
        LookupPassInput input;
        for (const VulkanBinding& b : bindings)
            if (b.declaration == "sampler2DArray uMaps2D[MAP_ARRAYS_2D]") input.mapBinding = std::uint32_t(b.binding);
        EXPECT_NE(lookup.find("binding " + std::to_string(input.mapBinding) + " = sampler2DArray uMaps2D"), std::string::npos);
        input.spirv = compileCompute(lookupCompute(lookup, true), name + "-lookup-vk-run", error);
        ASSERT_FALSE(input.spirv.empty()) << error;
        input.format = format->vk;
        input.resolution = resolution;
        for (const glm::vec4& m : stored)
            for (int k = 0; k < format->channels; ++k) {
                std::uint8_t bytes[4];
                if (format->bytes == 4) {
                    std::memcpy(bytes, &m[k], 4);
                } else {
                    const std::uint16_t v = format->unorm ? std::uint16_t(std::lround(double(m[k]) * 65535.0))
                                                          : glm::packHalf1x16(m[k]);
                    std::memcpy(bytes, &v, 2);
                }
                input.texels.insert(input.texels.end(), bytes, bytes + format->bytes);
            }
        input.addressMode = address == "wrap" ? VK_SAMPLER_ADDRESS_MODE_REPEAT
                            : address == "clamp" ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE
                                                 : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
        input.border = glm::vec4(border[0], border[1], border[2], border[3]);
        input.points = points;
        const LookupPassResult vk = runLookupVulkan(input);
        if (vk.noDevice) GTEST_SKIP() << "no Vulkan device (" << vk.error << "); scripts/install-deps installs lavapipe";
        ASSERT_EQ(vk.error, "");
        ASSERT_EQ(vk.shadow.size(), count);
        double maxDiff = 0.0, sum = 0.0;
        std::size_t over = 0, partial = 0, shadowed = 0;
        for (std::size_t i = 0; i < count; ++i) {
            const double d = std::abs(double(vk.shadow[i]) - double(glShadow[i]));
            maxDiff = std::max(maxDiff, d);
            sum += d;
            over += d > 1e-3;
            partial += glShadow[i] > 0.0f && glShadow[i] < 1.0f;
            shadowed += glShadow[i] < 0.5f;
        }
        std::printf("[ lavapipe ] %s (%s): exported Vulkan lookup vs exported GL lookup at %zu floor points (%zu partly "
                    "lit, %zu in shadow): max |dS| %.3g, mean %.3g, %zu over 1e-3\n",
                    name.c_str(), vk.deviceName.c_str(), count, partial, shadowed, maxDiff, sum / double(count), over);
        EXPECT_GT(shadowed, 100u) << "the grid crosses the shadows";
        EXPECT_GT(partial, 20u);
        EXPECT_LE(over, count / 200) << "points whose S differs by more than 1e-3 (0.5 % allowed)";
        EXPECT_LT(maxDiff, 5e-3) << "llvmpipe 15: at most 9e-4 (MSM), 2e-5 (VSM, EVSM)";
    }
}

}  // namespace shadowlab::test
