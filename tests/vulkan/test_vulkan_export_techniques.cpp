// Moments techniques (VSM, EVSM2/4, MSM) and PCSS exported: the snippet carries ShadowLab's own lookup GLSL
// (shaders/shadow/lookup.glsl with the technique's file), its moments and blur compute shaders
// (shaders/moments.comp.glsl) and their numbers. Checked here: every exported shader compiles with glslangValidator,
// as Vulkan SPIR-V (its descriptors bound) and as OpenGL GLSL, for each technique, precision and light kind; the
// exported GL compute shaders, run on ShadowLab's own depth map with the exported blur radius and weights, store
// exactly the moments ShadowLab's moments pass stores; and the Vulkan ones run on lavapipe (tests/vulkan/
// vulkan_compute_pass): the moments passes against ShadowLab's GL moments, the moments and PCSS lookups against the
// exported GL lookups. (The lookup's S against ShadowLab's main pass: tests/accuracy/test_export_techniques.cpp, which
// has the pixel probe.)
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
#include "shadow/shadow_map.h"
#include "vulkan_lookup_pass.h"

#include <glm/gtc/packing.hpp>
#include <glm/vec2.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <tuple>

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

// A moments storage format as the export names it (JSON technique.moments.format) in Vulkan, and its texels' bytes.
struct MomentStorage {
    const char* name;
    VkFormat vk;
    int channels;
    int bytes;  // per channel
    bool unorm;
};
const MomentStorage& momentStorage(const std::string& name) {
    static const MomentStorage formats[] = {
        {"rg16f", VK_FORMAT_R16G16_SFLOAT, 2, 2, false}, {"rg32f", VK_FORMAT_R32G32_SFLOAT, 2, 4, false},
        {"rgba16f", VK_FORMAT_R16G16B16A16_SFLOAT, 4, 2, false}, {"rgba32f", VK_FORMAT_R32G32B32A32_SFLOAT, 4, 4, false},
        {"rgba16", VK_FORMAT_R16G16B16A16_UNORM, 4, 2, true}};
    for (const MomentStorage& f : formats)
        if (name == f.name) return f;
    throw std::runtime_error("no Vulkan format for the exported moments format " + name);
}

// Moments (GL's read-back floats, each exactly a value of the storage) as the storage's texels.
std::vector<std::uint8_t> momentTexels(const std::vector<glm::vec4>& moments, const MomentStorage& f) {
    std::vector<std::uint8_t> texels;
    for (const glm::vec4& m : moments)
        for (int k = 0; k < f.channels; ++k) {
            std::uint8_t bytes[4];
            if (f.bytes == 4) {
                std::memcpy(bytes, &m[k], 4);
            } else {
                const std::uint16_t v = f.unorm ? std::uint16_t(std::lround(double(m[k]) * 65535.0)) : glm::packHalf1x16(m[k]);
                std::memcpy(bytes, &v, 2);
            }
            texels.insert(texels.end(), bytes, bytes + f.bytes);
        }
    return texels;
}

// The storage's texels as floats (the channels it has; the rest 0).
std::vector<glm::vec4> momentsOfTexels(const std::vector<std::uint8_t>& texels, const MomentStorage& f) {
    const std::size_t stride = std::size_t(f.channels * f.bytes);
    std::vector<glm::vec4> out(texels.size() / stride, glm::vec4(0.0f));
    for (std::size_t i = 0; i < out.size(); ++i)
        for (int k = 0; k < f.channels; ++k) {
            const std::uint8_t* at = texels.data() + i * stride + std::size_t(k * f.bytes);
            if (f.bytes == 4) {
                std::memcpy(&out[i][k], at, 4);
            } else {
                std::uint16_t v;
                std::memcpy(&v, at, 2);
                out[i][k] = f.unorm ? float(double(v) / 65535.0) : glm::unpackHalf1x16(v);
            }
        }
    return out;
}

// The binding the export gave a uniform, by its name ("uOut") or declaration ("sampler2DArray uMaps2D[...]").
std::uint32_t exportedBinding(const std::vector<VulkanBinding>& bindings, const std::string& nameOrDeclaration) {
    for (const VulkanBinding& b : bindings)
        if (b.name == nameOrDeclaration || b.declaration == nameOrDeclaration) return std::uint32_t(b.binding);
    throw std::runtime_error("the export binds no " + nameOrDeclaration);
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
    struct Case { FilterKind kind; int bits; float blur; LightType light = LightType::Directional; bool mips = false; };
    for (const Case& c : {Case{FilterKind::Vsm, 32, 5.0f}, Case{FilterKind::Evsm4, 16, 4.5f}, Case{FilterKind::Msm, 16, 7.0f},
                          Case{FilterKind::Msm, 32, 1.0f}, Case{FilterKind::Evsm2, 32, 5.0f, LightType::Spot},
                          Case{FilterKind::Vsm, 32, 3.0f, LightType::Directional, true},
                          Case{FilterKind::Msm, 16, 3.0f, LightType::Directional, true}}) {
        Settings s = loadShippedPreset("default");
        // A spot light: perspective depth, which the convert pass stores linear (uPerspective, uNearFar).
        if (c.light == LightType::Spot) s.lights[0] = caseSettings({c.kind, c.bits, c.light, false, false}).lights[0];
        s.filter.kind = c.kind;
        s.filter.momentBits = c.bits;
        s.filter.blurWidth = c.blur;
        s.filter.positiveExponent = 40.0f;  // clamped at 16 bits
        s.filter.momentMips = c.mips;
        const int resolution = s.lights[0].shadow.resolution = 128;
        const std::string name = std::string(filterTechnique(c.kind).name) + "-" + std::to_string(c.bits) + "-" +
                                 lightTypeName(c.light) + (c.mips ? "-mips" : "");
        SCOPED_TRACE(name);
        const View view = renderView(renderer, scene, s, 32, 32);
        ASSERT_TRUE(view.stats.ok) << view.stats.error;
        const std::vector<glm::vec4> expected = renderer.viewMoments({0, ShadowViewKind::Single, 0}, 0, 0, resolution, resolution);
        ASSERT_EQ(expected.size(), std::size_t(resolution * resolution));
        ASSERT_NE(renderer.viewMap(0, -1), nullptr);
        const std::vector<float> depth = renderer.viewMap(0, -1)->readDepth();

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
        const int levels = moments["levels"];
        ASSERT_EQ(levels, c.mips ? 8 : 1) << "128 down to 1";
        glTextureStorage3D(out.id(), levels, format, resolution, resolution, 1);
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
        // The mips pass, as the snippet says, before the blur: level l from level l - 1, uSize = the level's size.
        EXPECT_EQ(moments.contains("mipsGlsl"), c.mips);
        if (c.mips) {
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            const gl::Program mips = gl::buildProgram({{GL_COMPUTE_SHADER, "exported mips", moments["mipsGlsl"]}}, {});
            glUseProgram(mips.id());
            for (int level = 1; level < levels; ++level) {
                const int size = std::max(resolution >> level, 1);
                glUniform1i(glGetUniformLocation(mips.id(), "uSize"), size);
                glBindImageTexture(1, out.id(), level - 1, GL_FALSE, 0, GL_READ_ONLY, format);
                glBindImageTexture(0, out.id(), level, GL_FALSE, 0, GL_WRITE_ONLY, format);
                glDispatchCompute(GLuint((size + 7) / 8), GLuint((size + 7) / 8), 1);
                glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            }
        }
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
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
        glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
        std::size_t differing = 0, texels = 0;
        for (int level = 0; level < levels; ++level) {
            const int size = std::max(resolution >> level, 1);
            const std::vector<glm::vec4> want =
                level == 0 ? expected : renderer.viewMoments({0, ShadowViewKind::Single, 0}, 0, 0, size, size, level);
            ASSERT_EQ(want.size(), std::size_t(size * size)) << "ShadowLab's level " << level;
            std::vector<glm::vec4> got(want.size());
            glGetTextureSubImage(out.id(), level, 0, 0, 0, size, size, 1, GL_RGBA, GL_FLOAT,
                                 GLsizei(got.size() * sizeof(glm::vec4)), got.data());
            for (std::size_t i = 0; i < got.size(); ++i) differing += got[i] != want[i];
            texels += got.size();
        }
        EXPECT_EQ(differing, 0u) << "texels whose exported moments differ from ShadowLab's";
        std::printf("[ export ] %s: the exported moments passes (%s, blur radius %d, %d levels) equal ShadowLab's at %zu "
                    "of %zu texels\n", name.c_str(), moments["glFormat"].get<std::string>().c_str(), radius, levels,
                    texels - differing, texels);
    }
}

namespace {

// The wrapper the GL and Vulkan runs put around an exported lookup: S of each point (world position, then normal).
// PCSS's rotation hashes gl_FragCoord, which a compute shader lacks: both runs read the same stand-in instead, the
// point's cell in a 64-wide grid (the lookup's own text otherwise unchanged).
std::string lookupCompute(std::string lookup, bool vulkan) {
    const std::string set = vulkan ? "set = 0, " : "";
    for (std::size_t at = lookup.find("gl_FragCoord"); at != std::string::npos; at = lookup.find("gl_FragCoord", at))
        lookup.replace(at, 12, "gPointCoord");
    return "#version 450 core\nlayout(local_size_x = 64) in;\nvec4 gPointCoord;\n" + lookup + "layout(std430, " + set +
           "binding = 10) readonly buffer Points { vec4 points[]; };\nlayout(std430, " + set +
           "binding = 11) writeonly buffer Shadows { float shadows[]; };\n"
           "void main() {\n    uint i = gl_GlobalInvocationID.x;\n    if (i >= uint(points.length() / 2)) return;\n"
           "    gPointCoord = vec4(float(i % 64u) + 0.5, float(i / 64u) + 0.5, 0.5, 1.0);\n"
           "    shadows[i] = light0Shadow(0, points[2u * i].xyz, normalize(points[2u * i + 1u].xyz));\n}\n";
}

// Surface points: a 64 x 64 grid over the floor (its top, the scene's lowest y), normal up, render-origin-relative.
std::vector<glm::vec4> floorGrid(const Scene& scene, const glm::dvec3& renderOrigin) {
    std::vector<glm::vec4> points;
    const glm::dvec3 lo = scene.bounds.min, hi = scene.bounds.max;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const glm::dvec3 p(lo.x + (hi.x - lo.x) * (i + 0.5) / 64.0, lo.y, lo.z + (hi.z - lo.z) * (j + 0.5) / 64.0);
            points.push_back(glm::vec4(glm::vec3(p - renderOrigin), 1.0f));
            points.push_back(glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
        }
    return points;
}

// The GL run: `program` (lookupCompute's, maps bound by the caller) at `points`; S per point.
std::vector<float> glLookupShadows(const gl::Program& program, const std::vector<glm::vec4>& points) {
    const std::size_t count = points.size() / 2;
    gl::Buffer pointBuffer = gl::createBuffer(), shadowBuffer = gl::createBuffer();
    glNamedBufferData(pointBuffer.id(), GLsizeiptr(points.size() * sizeof(glm::vec4)), points.data(), GL_STATIC_DRAW);
    glNamedBufferData(shadowBuffer.id(), GLsizeiptr(count * sizeof(float)), nullptr, GL_STATIC_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, pointBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 11, shadowBuffer.id());
    glUseProgram(program.id());
    glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> shadow(count);
    glGetNamedBufferSubData(shadowBuffer.id(), 0, GLsizeiptr(count * sizeof(float)), shadow.data());
    return shadow;
}

// Vulkan S against GL S at the same points, printed and checked: at most 0.5 % of the points differ by more than 1e-3
// and none by 5e-3 (llvmpipe / lavapipe: bilinear weights and exp/log differ in the last bits).
void expectSameShadows(const std::string& name, const LookupPassResult& vk, const std::vector<float>& glShadow) {
    const std::size_t count = glShadow.size();
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

VkSamplerAddressMode vulkanAddress(const std::string& address) {
    return address == "wrap" ? VK_SAMPLER_ADDRESS_MODE_REPEAT
           : address == "clamp" ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE
                                : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
}

GLint glAddress(const std::string& address) {
    return address == "wrap" ? GL_REPEAT : address == "clamp" ? GL_CLAMP_TO_EDGE : GL_CLAMP_TO_BORDER;
}

}  // namespace

// The exported Vulkan lookup of each moments technique, run by lavapipe on ShadowLab's stored moments (in the exported
// format, sampler and border, at the exported binding), gives the S the exported GL lookup gives in GL at the same
// surface points (a grid over the textbook's floor), which tests/accuracy/test_export_techniques.cpp ties to
// ShadowLab's main pass.
TEST_F(GlTest, ExportedMomentsLookupOnLavapipeGivesTheShadowGlGives) {
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
        const MomentStorage& format = momentStorage(moments["format"]);
        const std::vector<glm::vec4> points = floorGrid(scene, e.renderOrigin);

        // GL: the exported GL lookup on the same moments, through the exported sampler.
        const GLenum glFormat = momentInternalFormat(filterTechnique(c.kind), c.bits);
        gl::Texture map = gl::createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(map.id(), 1, glFormat, resolution, resolution, 1);
        glTextureSubImage3D(map.id(), 0, 0, 0, 0, resolution, resolution, 1, GL_RGBA, GL_FLOAT, stored.data());
        const std::vector<float> border = moments["border"];
        const std::string address = json["sampler"]["addressMode"];
        gl::Sampler sampler = gl::createSampler();
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_S, glAddress(address));
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, glAddress(address));
        glSamplerParameterfv(sampler.id(), GL_TEXTURE_BORDER_COLOR, border.data());
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        const gl::Program program = gl::buildProgram(
            {{GL_COMPUTE_SHADER, "exported lookup (GL)", lookupCompute(json["technique"]["lookupGlsl"], false)}}, {});
        glProgramUniform1i(program.id(), glGetUniformLocation(program.id(), "uMaps2D[0]"), 0);
        glBindTextureUnit(0, map.id());
        glBindSampler(0, sampler.id());
        const std::vector<float> glShadow = glLookupShadows(program, points);
        glBindSampler(0, 0);

        // Vulkan: the exported Vulkan lookup, the map at the binding the export names.
        std::vector<VulkanBinding> bindings;
        const std::string lookup = techniqueLookupCode(e, true, &bindings);
        LookupPassInput input;
        VkRunSampler momentsSampler;
        momentsSampler.linear = true;
        momentsSampler.address = vulkanAddress(address);
        momentsSampler.border = glm::vec4(border[0], border[1], border[2], border[3]);
        const std::uint32_t mapBinding = exportedBinding(bindings, "sampler2DArray uMaps2D[MAP_ARRAYS_2D]");
        input.maps = {{mapBinding, momentsSampler}};
        EXPECT_NE(lookup.find("binding " + std::to_string(mapBinding) + " = sampler2DArray uMaps2D"), std::string::npos);
        input.spirv = compileCompute(lookupCompute(lookup, true), name + "-lookup-vk-run", error);
        ASSERT_FALSE(input.spirv.empty()) << error;
        input.format = format.vk;
        input.resolution = resolution;
        input.texels = momentTexels(stored, format);
        input.points = points;
        const LookupPassResult vk = runLookupVulkan(input);
        if (vk.noDevice) GTEST_SKIP() << "no Vulkan device (" << vk.error << "); scripts/install-deps installs lavapipe";
        expectSameShadows(name, vk, glShadow);
    }
}

// The exported Vulkan PCSS lookup, run by lavapipe on ShadowLab's depth map (a D32 image read through the exported
// comparison sampler and the plain nearest one, at the bindings the export names), gives the S the exported GL lookup
// gives in GL at the same floor points, for a directional and a spot light with a size (so the blocker search and
// the widened filter both act). PCSS before this test was compiled for Vulkan only.
TEST_F(GlTest, ExportedPcssLookupOnLavapipeGivesTheShadowGlGives) {
    const Scene scene = loadBuiltin("textbook");
    Renderer renderer;
    for (const LightType light : {LightType::Directional, LightType::Spot}) {
        Settings s = caseSettings({FilterKind::Pcss, 32, light, false, false});
        const int resolution = s.lights[0].shadow.resolution = 256;
        const std::string name = std::string("pcss-") + lightTypeName(light);
        SCOPED_TRACE(name);
        const View view = renderView(renderer, scene, s, 32, 32);
        ASSERT_TRUE(view.stats.ok) << view.stats.error;
        const ShadowMap* depthMap = renderer.viewMap(0, -1);
        ASSERT_NE(depthMap, nullptr);
        const std::vector<float> depth = depthMap->readDepth();
        ASSERT_EQ(depth.size(), std::size_t(resolution * resolution));
        std::string error;
        const std::optional<ShadowExportSet> set = exportForScene(s, scene, "builtin:textbook", 0, error);
        ASSERT_TRUE(set && set->lights.at(0).shadow) << error;
        const ShadowExport& e = *set->lights[0].shadow;
        const nlohmann::json json = nlohmann::json::parse(exportSnippet(e, ExportFormat::Json));
        const nlohmann::json& exportedSampler = json["sampler"];
        const std::string address = exportedSampler["addressMode"];
        const float border = exportedSampler["borderStored"];
        const bool greaterEqual = exportedSampler["compare"] == "GEQUAL";
        const std::vector<glm::vec4> points = floorGrid(scene, e.renderOrigin);

        // GL: the depth map as a 2D array, a comparison sampler (uMaps2D) and a plain nearest one (uDepth2D).
        gl::Texture map = gl::createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(map.id(), 1, GL_DEPTH_COMPONENT32F, resolution, resolution, 1);
        glTextureSubImage3D(map.id(), 0, 0, 0, 0, resolution, resolution, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
        gl::Sampler compare = gl::createSampler(), plain = gl::createSampler();
        const float borderColour[4] = {border, border, border, border};
        for (const GLuint sampler : {compare.id(), plain.id()}) {
            glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, glAddress(address));
            glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, glAddress(address));
            glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, borderColour);
        }
        glSamplerParameteri(compare.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glSamplerParameteri(compare.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glSamplerParameteri(compare.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glSamplerParameteri(compare.id(), GL_TEXTURE_COMPARE_FUNC, greaterEqual ? GL_GEQUAL : GL_LEQUAL);
        glSamplerParameteri(plain.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glSamplerParameteri(plain.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        const gl::Program program = gl::buildProgram(
            {{GL_COMPUTE_SHADER, "exported PCSS lookup (GL)", lookupCompute(json["technique"]["lookupGlsl"], false)}}, {});
        glProgramUniform1i(program.id(), glGetUniformLocation(program.id(), "uMaps2D[0]"), 0);
        glProgramUniform1i(program.id(), glGetUniformLocation(program.id(), "uDepth2D[0]"), 1);
        glBindTextureUnit(0, map.id());
        glBindTextureUnit(1, map.id());
        glBindSampler(0, compare.id());
        glBindSampler(1, plain.id());
        const std::vector<float> glShadow = glLookupShadows(program, points);
        glBindSampler(0, 0);
        glBindSampler(1, 0);

        // Vulkan: the exported Vulkan lookup, both samplers at the bindings the export names.
        std::vector<VulkanBinding> bindings;
        const std::string lookup = techniqueLookupCode(e, true, &bindings);
        LookupPassInput input;
        VkRunSampler compareSampler, plainSampler;
        compareSampler.linear = true;
        compareSampler.compare = true;
        compareSampler.compareOp = greaterEqual ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL;
        compareSampler.address = plainSampler.address = vulkanAddress(address);
        ASSERT_TRUE(border == 0.0f || border == 1.0f) << "a standard border colour (a depth image has no custom one here)";
        compareSampler.border = plainSampler.border = glm::vec4(border);
        input.maps = {{exportedBinding(bindings, "sampler2DArrayShadow uMaps2D[MAP_ARRAYS_2D]"), compareSampler},
                      {exportedBinding(bindings, "sampler2DArray uDepth2D[MAP_ARRAYS_2D]"), plainSampler}};
        input.spirv = compileCompute(lookupCompute(lookup, true), name + "-lookup-vk-run", error);
        ASSERT_FALSE(input.spirv.empty()) << error;
        input.format = VK_FORMAT_D32_SFLOAT;
        input.resolution = resolution;
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(depth.data());
        input.texels.assign(bytes, bytes + depth.size() * sizeof(float));
        input.points = points;
        const LookupPassResult vk = runLookupVulkan(input);
        if (vk.noDevice) GTEST_SKIP() << "no Vulkan device (" << vk.error << "); scripts/install-deps installs lavapipe";
        expectSameShadows(name, vk, glShadow);
    }
}

// The exported Vulkan moments passes (convert, then the blur's two directions), run by lavapipe on ShadowLab's depth
// map with the exported shaders, bindings, std140 blocks, radius, weights and mips, store the moments ShadowLab's GL
// moments pass stores: float storage bit for bit, unorm storage within one step (its rounding; see the check below).
// A spot light's case checks its linear depth (uPerspective, uNearFar baked in).
TEST_F(GlTest, ExportedVulkanMomentsPassesOnLavapipeStoreShadowLabsMoments) {
    const Scene scene = loadBuiltin("textbook");
    Renderer renderer;
    struct Case { FilterKind kind; int bits; float blur; LightType light; bool mips = false; };
    for (const Case& c : {Case{FilterKind::Vsm, 32, 5.0f, LightType::Directional},
                          Case{FilterKind::Evsm4, 16, 4.5f, LightType::Directional},
                          Case{FilterKind::Msm, 16, 7.0f, LightType::Directional},
                          Case{FilterKind::Msm, 32, 3.0f, LightType::Directional},
                          Case{FilterKind::Evsm2, 32, 5.0f, LightType::Spot},
                          Case{FilterKind::Vsm, 32, 3.0f, LightType::Directional, true}}) {
        Settings s = caseSettings({c.kind, c.bits, c.light, false, false});
        s.filter.blurWidth = c.blur;
        s.filter.momentMips = c.mips;
        s.filter.positiveExponent = 40.0f;  // clamped at 16 bits
        const int resolution = s.lights[0].shadow.resolution;
        const std::string name = std::string(filterTechnique(c.kind).name) + "-" + std::to_string(c.bits) + "-" +
                                 lightTypeName(c.light) + (c.mips ? "-mips" : "");
        SCOPED_TRACE(name);
        const View view = renderView(renderer, scene, s, 32, 32);
        ASSERT_TRUE(view.stats.ok) << view.stats.error;
        const std::vector<glm::vec4> expected = renderer.viewMoments({0, ShadowViewKind::Single, 0}, 0, 0, resolution, resolution);
        ASSERT_EQ(expected.size(), std::size_t(resolution * resolution));
        const ShadowMap* depthMap = renderer.viewMap(0, -1);
        ASSERT_NE(depthMap, nullptr);
        const std::vector<float> depth = depthMap->readDepth();
        std::string error;
        const std::optional<ShadowExportSet> set = exportForScene(s, scene, "builtin:textbook", 0, error);
        ASSERT_TRUE(set && set->lights.at(0).shadow) << error;
        const ShadowExport& e = *set->lights[0].shadow;
        const nlohmann::json moments = nlohmann::json::parse(exportSnippet(e, ExportFormat::Json))["technique"]["moments"];
        const MomentStorage& format = momentStorage(moments["format"]);
        const MomentsPassShaders passes = momentsPassShaders(e, true);
        const std::vector<std::uint32_t> convert = compileCompute(passes.convert, name + "-convert-vk-run", error);
        ASSERT_FALSE(convert.empty()) << error;
        const std::vector<std::uint32_t> blur = compileCompute(passes.blur, name + "-blur-vk-run", error);
        ASSERT_FALSE(blur.empty()) << error;
        const int levels = moments["levels"];
        const std::vector<std::uint32_t> mips = c.mips ? compileCompute(passes.mips, name + "-mips-vk-run", error)
                                                       : std::vector<std::uint32_t>();
        ASSERT_EQ(mips.empty(), !c.mips) << error;

        // Images: 0 the depth map (plain floats, as the convert pass reads it), 1 the moments, 2 the blur's scratch.
        VkRun run;
        const auto* depthBytes = reinterpret_cast<const std::uint8_t*>(depth.data());
        run.images.push_back({VK_FORMAT_R32_SFLOAT, resolution, 1, 4,
                              std::vector<std::uint8_t>(depthBytes, depthBytes + depth.size() * sizeof(float))});
        run.images.push_back({format.vk, resolution, levels, format.channels * format.bytes, {}});
        run.images.push_back({format.vk, resolution, 1, format.channels * format.bytes, {}});
        // Uniform blocks (std140, as the export's Vulkan comment says): 0 uLayer, 1 uRadius, 2 uWeights, 3 / 4 uDirection.
        const nlohmann::json& viewBlur = moments["blur"].at(0);
        const int radius = viewBlur["radius"];
        std::vector<float> weights = viewBlur["weights"];
        weights.resize(32, 0.0f);  // the block holds uWeights[32], each at a 16-byte stride
        run.buffers = {std140Value(0), std140Value(radius), std140Array(weights),
                       std140Value(glm::ivec2(1, 0)), std140Value(glm::ivec2(0, 1))};
        const auto bind = [](const std::vector<VulkanBinding>& b, const char* uniform, VkDescriptorType type, int image,
                             int buffer) {
            VkRunBinding r;
            r.binding = exportedBinding(b, uniform);
            r.type = type;
            r.image = image;
            r.buffer = buffer;
            return r;
        };
        const std::uint32_t groups = std::uint32_t((resolution + 7) / 8);
        run.dispatches.push_back({convert,
                                  {bind(passes.convertBindings, "uOut", VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, -1),
                                   bind(passes.convertBindings, "uDepth", VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 0, -1),
                                   bind(passes.convertBindings, "uLayer", VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, -1, 0)},
                                  groups, groups});
        // The mips pass per level, before the blur: uIn = level l - 1, uOut = level l, uSize its size (a block).
        for (int level = 1; level < levels; ++level) {
            const int size = std::max(resolution >> level, 1);
            run.buffers.push_back(std140Value(size));
            VkRunBinding in = bind(passes.mipsBindings, "uIn", VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, -1);
            VkRunBinding out = bind(passes.mipsBindings, "uOut", VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, -1);
            in.level = level - 1;
            out.level = level;
            run.dispatches.push_back({mips,
                                      {in, out, bind(passes.mipsBindings, "uSize", VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, -1,
                                                     int(run.buffers.size()) - 1)},
                                      std::uint32_t((size + 7) / 8), std::uint32_t((size + 7) / 8)});
        }
        for (const auto& [from, to, direction] : {std::tuple{1, 2, 3}, std::tuple{2, 1, 4}})
            if (radius > 0)
                run.dispatches.push_back({blur,
                                          {bind(passes.blurBindings, "uIn", VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, from, -1),
                                           bind(passes.blurBindings, "uOut", VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, to, -1),
                                           bind(passes.blurBindings, "uRadius", VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, -1, 1),
                                           bind(passes.blurBindings, "uWeights", VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, -1, 2),
                                           bind(passes.blurBindings, "uDirection", VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, -1, direction)},
                                          groups, groups});
        const VkRunResult vk = runComputeVulkan(run);
        if (vk.noDevice) GTEST_SKIP() << "no Vulkan device (" << vk.error << "); scripts/install-deps installs lavapipe";
        ASSERT_EQ(vk.error, "");
        // Every level, ShadowLab's one after another as the read-back holds them.
        const std::vector<glm::vec4> got = momentsOfTexels(vk.images.at(1), format);
        std::vector<glm::vec4> wanted = expected;
        for (int level = 1; level < levels; ++level) {
            const int size = std::max(resolution >> level, 1);
            const std::vector<glm::vec4> m = renderer.viewMoments({0, ShadowViewKind::Single, 0}, 0, 0, size, size, level);
            ASSERT_EQ(m.size(), std::size_t(size * size)) << "ShadowLab's level " << level;
            wanted.insert(wanted.end(), m.begin(), m.end());
        }
        ASSERT_EQ(got.size(), wanted.size());
        // Differences in units of the storage's step at each value (16-bit: half-float ulp or 1/65535; 32-bit: float ulp).
        double maxUlps = 0.0, maxAbs = 0.0;
        std::size_t differing = 0;
        for (std::size_t i = 0; i < got.size(); ++i) {
            bool differs = false;
            for (int k = 0; k < format.channels; ++k) {
                const double a = got[i][k], b = wanted[i][k];
                const double step = format.unorm ? 1.0 / 65535.0
                                    : format.bytes == 2 ? std::max(std::ldexp(1.0, std::ilogb(std::max(std::abs(b), 6.1e-5)) - 10), 5.96e-8)
                                                        : std::max(double(std::nextafter(std::abs(float(b)), INFINITY)) - std::abs(b), 1.4e-45);
                maxUlps = std::max(maxUlps, std::abs(a - b) / step);
                maxAbs = std::max(maxAbs, std::abs(a - b));
                differs |= a != b;
            }
            differing += differs;
        }
        std::printf("[ lavapipe ] %s (%s, %s, blur radius %d, %d levels): exported Vulkan moments passes vs ShadowLab's "
                    "GL passes: %zu of %zu texels differ, max %.3g storage steps (max |d| %.3g)\n",
                    name.c_str(), vk.deviceName.c_str(), moments["format"].get<std::string>().c_str(), radius, levels,
                    differing, got.size(), maxUlps, maxAbs);
        // Float storage: bit for bit (the same shader text, the same arithmetic). MSM's 16-bit unorm storage: within one
        // step (1/65535, plus the read-back's float rounding of v / 65535): its quantized moments land one step apart
        // after the convert pass already (llvmpipe 15: 616 of 16,384 texels without a blur, 666 after a radius-3 blur),
        // the rounding to unorm differing between Mesa's GL and Vulkan compiles of the same text.
        EXPECT_LE(maxUlps, format.unorm ? 1.001 : 0.0) << "storage steps between the exported Vulkan passes and ShadowLab's";
    }
}

}  // namespace shadowlab::test
