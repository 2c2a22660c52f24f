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

#include <nlohmann/json.hpp>

#include <cstdio>
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

}  // namespace shadowlab::test
