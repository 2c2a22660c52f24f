// The exported lookup of a moments technique (VSM, EVSM4, MSM) and of PCSS renders ShadowLab's shadow: at every
// surface pixel of the textbook view, the exported GLSL (from the JSON export: the lookup, the moments' format and
// border, nothing from ShadowLab's own objects but the stored maps) computes, in a GL fragment shader at that pixel,
// the shadow factor S of the pixel's surface point; ShadowLab's main pass wrote S there (the pixel probe reads it,
// with the point and normal from its G-buffer). They must agree within a stated bound.
#include "export/export_snippets.h"
#include "export/shadow_shader_code.h"
#include "gl/gl.h"
#include "gl/gl_objects.h"
#include "gl/program.h"
#include "gl_fixture.h"
#include "probe/pixel_probe.h"
#include "shading/filters/filter_technique.h"
#include "shadow/shadow_map.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadowlab::test {
namespace {

class ExportTechniques : public GlTest {};

constexpr int kWidth = 160, kHeight = 90;

struct Point {
    glm::vec3 world;   // minus the render origin
    glm::vec3 normal;
    glm::vec2 pixel;   // GL window coordinates of its pixel (row 0 = bottom)
    float shadowLab;   // S as ShadowLab's main pass wrote it
    glm::vec3 dx{0.0f}, dy{0.0f};  // the position's dFdxFine / dFdyFine there (a lookup that takes them)
};

// The exported lookup, evaluated by a point drawn at each pixel's centre (gl_FragCoord as the main pass had it, which
// PCSS's per-pixel rotation reads). `derivatives`: the lookup also takes the position's screen derivatives (a point
// has none of its own: each point brings the pixel's). Returns S per point.
std::vector<float> exportedShadow(const std::string& lookup, const std::vector<Point>& points, bool cube,
                                  const std::vector<std::pair<const char*, int>>& units, bool derivatives = false) {
    const std::string vertex =
        "#version 450 core\n"
        "layout(location = 0) in vec3 aWorld;\nlayout(location = 1) in vec3 aNormal;\nlayout(location = 2) in vec2 aPixel;\n"
        "layout(location = 3) in vec3 aDx;\nlayout(location = 4) in vec3 aDy;\n"
        "uniform vec2 uSize;\nout vec3 vWorld;\nout vec3 vNormal;\nflat out vec3 vDx;\nflat out vec3 vDy;\n"
        "void main() { gl_Position = vec4(aPixel / uSize * 2.0 - 1.0, 0.0, 1.0); gl_PointSize = 1.0; vWorld = aWorld; "
        "vNormal = aNormal; vDx = aDx; vDy = aDy; }\n";
    const std::string fragment = "#version 450 core\n" + lookup +
                                 "in vec3 vWorld;\nin vec3 vNormal;\nflat in vec3 vDx;\nflat in vec3 vDy;\n"
                                 "layout(location = 0) out float outShadow;\n"
                                 "void main() { outShadow = light0Shadow(" + std::string(cube ? "" : "0, ") +
                                 "vWorld, normalize(vNormal)" + (derivatives ? ", vDx, vDy" : "") + "); }\n";
    const gl::Program program = gl::buildProgram(
        {{GL_VERTEX_SHADER, "exported-test.vert", vertex}, {GL_FRAGMENT_SHADER, "exported lookup", fragment}}, {});
    gl::Texture target = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(target.id(), 1, GL_R32F, kWidth, kHeight);
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, target.id(), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, kWidth, kHeight);
    const float clear[4] = {-1.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(fbo, GL_COLOR, 0, clear);
    std::vector<float> attributes;
    for (const Point& p : points)
        for (float v : {p.world.x, p.world.y, p.world.z, p.normal.x, p.normal.y, p.normal.z, p.pixel.x, p.pixel.y,
                        p.dx.x, p.dx.y, p.dx.z, p.dy.x, p.dy.y, p.dy.z})
            attributes.push_back(v);
    gl::Buffer buffer = gl::createBuffer();
    glNamedBufferData(buffer.id(), GLsizeiptr(attributes.size() * sizeof(float)), attributes.data(), GL_STATIC_DRAW);
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    glVertexArrayVertexBuffer(vao, 0, buffer.id(), 0, 14 * sizeof(float));
    const GLuint offsets[5] = {0, 3, 6, 8, 11};  // world, normal, pixel, dx, dy (floats)
    for (GLuint a = 0; a < 5; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, a == 2 ? 2 : 3, GL_FLOAT, GL_FALSE, offsets[a] * sizeof(float));
        glVertexArrayAttribBinding(vao, a, 0);
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program.id());
    glUniform2f(glGetUniformLocation(program.id(), "uSize"), float(kWidth), float(kHeight));
    for (const auto& [sampler, unit] : units) {
        const GLint location = glGetUniformLocation(program.id(), sampler);
        EXPECT_GE(location, 0) << "the exported lookup reads " << sampler;
        glUniform1i(location, unit);
    }
    glBindVertexArray(vao);
    glDrawArrays(GL_POINTS, 0, GLsizei(points.size()));
    std::vector<float> picture(std::size_t(kWidth) * kHeight);
    glGetTextureImage(target.id(), 0, GL_RED, GL_FLOAT, GLsizei(picture.size() * sizeof(float)), picture.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteVertexArrays(1, &vao);
    glDeleteFramebuffers(1, &fbo);
    std::vector<float> out;
    for (const Point& p : points) out.push_back(picture[std::size_t(p.pixel.y) * kWidth + std::size_t(p.pixel.x)]);
    return out;
}

GLint wrapOf(const std::string& address) {
    return address == "wrap" ? GL_REPEAT : address == "clamp" ? GL_CLAMP_TO_EDGE : GL_CLAMP_TO_BORDER;
}

// The exported S against the main pass's at the points, printed (`what`: which lookup, `extra`: more of the setup)
// and checked. Measured (llvmpipe): VSM, EVSM4, PCSS none over 1e-3 (max 1.5e-4); MSM 11-18 pixels (0.2-0.3 %, max
// 0.018): Hamburger's bound is ill-conditioned near the caster, so the G-buffer's point (the probe's) against the main
// pass's interpolated one moves it there. Bound: 0.5 % of the pixels, mean 1e-4.
void expectMainPassShadow(const std::string& name, const char* what, const std::string& extra,
                          const std::vector<float>& exported, const std::vector<Point>& points) {
    double maxDiff = 0.0, sumDiff = 0.0;
    std::size_t over = 0, partial = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double d = std::abs(double(exported[i]) - double(points[i].shadowLab));
        maxDiff = std::max(maxDiff, d);
        sumDiff += d;
        over += d > 1e-3;
        partial += points[i].shadowLab > 0.0f && points[i].shadowLab < 1.0f;
    }
    std::printf("[ export ] %s: exported %s vs ShadowLab's main pass at %zu surface pixels (%zu partly lit%s): "
                "max |dS| %.3g, mean %.3g, %zu pixels over 1e-3\n",
                name.c_str(), what, points.size(), partial, extra.c_str(), maxDiff, sumDiff / double(points.size()), over);
    EXPECT_GT(partial, 50u) << "soft edges are compared, not only 0 and 1";
    EXPECT_LE(double(over), 0.005 * double(points.size())) << "pixels whose exported S differs by more than 1e-3";
    EXPECT_LT(sumDiff / double(points.size()), 1e-4);
}

}  // namespace

TEST_F(ExportTechniques, ExportedLookupRendersShadowLabsShadowForEveryMomentsTechniqueAndPcss) {
    const Scene scene = loadBuiltin("textbook");
    struct Case { FilterKind kind; int bits; };
    for (const Case& c : {Case{FilterKind::Vsm, 32}, Case{FilterKind::Evsm4, 32}, Case{FilterKind::Msm, 16},
                          Case{FilterKind::Msm, 32}, Case{FilterKind::Pcss, 32}}) {
        Settings s = loadShippedPreset("default");
        s.filter.kind = c.kind;
        s.filter.momentBits = c.bits;
        s.filter.blurWidth = 5.0f;
        s.filter.bleedReduction = 0.2f;
        s.lights[0].size = 2.0f;  // PCSS's penumbra (the moments techniques ignore it)
        s.lights[0].shadow.receiverPlaneBias = false;  // a point drawn per pixel has no screen derivatives
        const int resolution = s.lights[0].shadow.resolution = 512;
        const std::string name = std::string(filterTechnique(c.kind).name) + "-" + std::to_string(c.bits);
        SCOPED_TRACE(name);

        Renderer renderer;
        PixelProbe probe;
        const Camera camera = cameraFor(s.camera, scene, double(kWidth) / kHeight);
        ASSERT_EQ(probe.capture(renderer, scene, s, camera, kWidth, kHeight), "");
        std::string error;
        const std::optional<ShadowExportSet> set = exportForScene(s, scene, "builtin:textbook", 0, error);
        ASSERT_TRUE(set && set->lights.at(0).shadow) << error;
        const ShadowExport& e = *set->lights[0].shadow;
        const nlohmann::json json = nlohmann::json::parse(exportSnippet(e, ExportFormat::Json));
        const nlohmann::json& technique = json["technique"];

        std::vector<Point> points;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const PixelProbeReport r = probe.at(x, y);
                if (!r.ok) continue;
                points.push_back({glm::vec3(r.world - e.renderOrigin), glm::vec3(r.shadingNormal),
                                  glm::vec2(float(x) + 0.5f, float(kHeight - 1 - y) + 0.5f), float(r.shadowGpu)});
            }
        ASSERT_GT(points.size(), 5000u);

        // The maps as a user's program holds them, from the export's description: a 2D array of one layer.
        const std::vector<float> depth = renderer.shadowMap().readDepth();
        gl::Texture map = gl::createTexture(GL_TEXTURE_2D_ARRAY);
        gl::Sampler compare = gl::createSampler(), plain = gl::createSampler();
        if (c.kind == FilterKind::Pcss) {
            glTextureStorage3D(map.id(), 1, GL_DEPTH_COMPONENT32F, resolution, resolution, 1);
            glTextureSubImage3D(map.id(), 0, 0, 0, 0, resolution, resolution, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
            const GLint wrap = wrapOf(json["sampler"]["addressMode"]);
            const float border = json["sampler"]["borderStored"];
            const float borderColor[4] = {border, border, border, border};
            for (GLuint sampler : {compare.id(), plain.id()}) {
                glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, wrap);
                glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, wrap);
                glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, borderColor);
            }
            glSamplerParameteri(compare.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glSamplerParameteri(compare.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glSamplerParameteri(compare.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
            glSamplerParameteri(compare.id(), GL_TEXTURE_COMPARE_FUNC, json["sampler"]["compare"] == "GEQUAL" ? GL_GEQUAL : GL_LEQUAL);
            glSamplerParameteri(plain.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glSamplerParameteri(plain.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glBindTextureUnit(0, map.id());
            glBindSampler(0, compare.id());
            glBindTextureUnit(1, map.id());
            glBindSampler(1, plain.id());
        } else {
            const nlohmann::json& moments = technique["moments"];
            const GLenum format = momentInternalFormat(filterTechnique(c.kind), c.bits);
            ASSERT_EQ(moments["glFormat"], c.bits == 16 ? (c.kind == FilterKind::Msm ? "GL_RGBA16" : "GL_RGBA16F")
                                                        : (c.kind == FilterKind::Vsm ? "GL_RG32F" : "GL_RGBA32F"));
            const std::vector<glm::vec4> stored =
                renderer.viewMoments({0, ShadowViewKind::Single, 0}, 0, 0, resolution, resolution);
            ASSERT_EQ(stored.size(), std::size_t(resolution) * resolution);
            glTextureStorage3D(map.id(), 1, format, resolution, resolution, 1);
            glTextureSubImage3D(map.id(), 0, 0, 0, 0, resolution, resolution, 1, GL_RGBA, GL_FLOAT, stored.data());
            const GLint wrap = wrapOf(json["sampler"]["addressMode"]);
            const std::vector<float> border = moments["border"];
            glSamplerParameteri(plain.id(), GL_TEXTURE_WRAP_S, wrap);
            glSamplerParameteri(plain.id(), GL_TEXTURE_WRAP_T, wrap);
            glSamplerParameterfv(plain.id(), GL_TEXTURE_BORDER_COLOR, border.data());
            glSamplerParameteri(plain.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glSamplerParameteri(plain.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glBindTextureUnit(0, map.id());
            glBindSampler(0, plain.id());
        }
        // The samplers the lookup declares (its comment names them): the map on unit 0, PCSS's depths also on 1.
        const std::vector<float> exported =
            c.kind == FilterKind::Pcss ? exportedShadow(technique["lookupGlsl"], points, false, {{"uMaps2D[0]", 0}, {"uDepth2D[0]", 1}})
                                       : exportedShadow(technique["lookupGlsl"], points, false, {{"uMaps2D[0]", 0}});
        expectMainPassShadow(name, "lookup", "", exported, points);
    }
}

// A point light's exported depth lookup (renderer/export/shadow_shader_code.cpp's codeCube: the filter's taps moved
// across the face by the renderer's own cube_face_depth.glsl, printed into the snippet) renders the shadow ShadowLab's
// main pass renders at every surface pixel of the textbook lit by a point light: PCF 3x3 (bilinear taps) and Poisson
// (16 nearest taps at a radius), the cube map uploaded face by face from ShadowLab's stored faces.
TEST_F(ExportTechniques, ExportedCubeLookupRendersShadowLabsPointLightShadow) {
    const Scene scene = loadBuiltin("textbook");
    for (const FilterKind kind : {FilterKind::Pcf, FilterKind::Poisson}) {
        Settings s = loadShippedPreset("default");
        s.filter.kind = kind;
        s.filter.kernel = 3;
        LightSettings& l = s.lights[0];
        l.type = LightType::Point;
        l.position = {2.0f, 7.0f, 3.0f};
        const int resolution = l.shadow.resolution = 512;
        const std::string name = std::string(filterTechnique(kind).name) + "-point";
        SCOPED_TRACE(name);

        Renderer renderer;
        PixelProbe probe;
        const Camera camera = cameraFor(s.camera, scene, double(kWidth) / kHeight);
        ASSERT_EQ(probe.capture(renderer, scene, s, camera, kWidth, kHeight), "");
        std::string error;
        const std::optional<ShadowExportSet> set = exportForScene(s, scene, "builtin:textbook", 0, error);
        ASSERT_TRUE(set && set->lights.at(0).shadow) << error;
        const ShadowExport& e = *set->lights[0].shadow;
        const nlohmann::json json = nlohmann::json::parse(exportSnippet(e, ExportFormat::Json));
        std::vector<Point> points;
        std::size_t shadowed = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const PixelProbeReport r = probe.at(x, y);
                if (!r.ok) continue;
                points.push_back({glm::vec3(r.world - e.renderOrigin), glm::vec3(r.shadingNormal),
                                  glm::vec2(float(x) + 0.5f, float(kHeight - 1 - y) + 0.5f), float(r.shadowGpu)});
                shadowed += r.shadowGpu < 0.5;
            }
        ASSERT_GT(points.size(), 5000u);
        ASSERT_GT(shadowed, 200u) << "the view sees the point light's shadows";

        // The cube map as the export describes it: six faces in GL order, a comparison sampler, seamless filtering.
        gl::Texture cube = gl::createTexture(GL_TEXTURE_CUBE_MAP);
        glTextureStorage2D(cube.id(), 1, GL_DEPTH_COMPONENT32F, resolution, resolution);
        for (int face = 0; face < 6; ++face) {
            const ShadowMap* map = renderer.viewMap(0, face);
            ASSERT_NE(map, nullptr) << "face " << face;
            const std::vector<float> depth = map->readDepth();
            glTextureSubImage3D(cube.id(), 0, 0, 0, face, resolution, resolution, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
        }
        gl::Sampler compare = gl::createSampler();
        const GLint filter = json["sampler"]["filter"] == "linear" ? GL_LINEAR : GL_NEAREST;
        glSamplerParameteri(compare.id(), GL_TEXTURE_MIN_FILTER, filter);
        glSamplerParameteri(compare.id(), GL_TEXTURE_MAG_FILTER, filter);
        glSamplerParameteri(compare.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glSamplerParameteri(compare.id(), GL_TEXTURE_COMPARE_FUNC, json["sampler"]["compare"] == "GEQUAL" ? GL_GEQUAL : GL_LEQUAL);
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
        glBindTextureUnit(0, cube.id());
        glBindSampler(0, compare.id());
        const std::string lookup = shadowShaderCode(e, shaderTargetFor(ExportFormat::GL, e.reversedZ));
        EXPECT_NE(exportSnippet(e, ExportFormat::GL).find(lookup), std::string::npos) << "the snippet holds the lookup";
        EXPECT_NE(lookup.find("CubeFaceFrame cubeFaceFrame("), std::string::npos) << "the renderer's cube_face_depth.glsl";
        // The caller's side: the map as a uniform, S of a point (the exported function takes the map first).
        const std::vector<float> exported = exportedShadow(
            lookup + "uniform samplerCubeShadow uCube;\n"
                     "float light0Shadow(vec3 worldPos, vec3 n) { return light0Shadow(uCube, worldPos, n); }\n",
            points, true, {{"uCube", 0}});
        glBindSampler(0, 0);
        expectMainPassShadow(name, "cube lookup", ", " + std::to_string(shadowed) + " in shadow", exported, points);
    }
}

// filter.momentMips exported: ShadowLab's moments levels (the exported mips pass writes them bit for bit:
// tests/vulkan/test_vulkan_export_techniques.cpp) read by the exported lookup compiled with MOMENT_MIPS, which takes the
// pixel's position derivatives, render the main pass's trilinear shadow at every surface pixel whose 2x2 quad lies on
// one triangle (there the position's dFdxFine / dFdyFine are the differences of the probe's points across the quad).
TEST_F(ExportTechniques, ExportedMipsLookupRendersShadowLabsTrilinearShadow) {
    const Scene scene = loadBuiltin("textbook");
    for (const FilterKind kind : {FilterKind::Vsm, FilterKind::Msm}) {
        Settings s = loadShippedPreset("default");
        s.filter.kind = kind;
        s.filter.momentBits = 32;
        s.filter.blurWidth = 3.0f;
        s.filter.bleedReduction = 0.2f;
        s.filter.momentMips = true;
        s.lights[0].shadow.receiverPlaneBias = false;
        const int resolution = s.lights[0].shadow.resolution = 1024;
        const std::string name = std::string(filterTechnique(kind).name) + "-mips";
        SCOPED_TRACE(name);

        Renderer renderer;
        PixelProbe probe;
        const Camera camera = cameraFor(s.camera, scene, double(kWidth) / kHeight);
        ASSERT_EQ(probe.capture(renderer, scene, s, camera, kWidth, kHeight), "");
        std::string error;
        const std::optional<ShadowExportSet> set = exportForScene(s, scene, "builtin:textbook", 0, error);
        ASSERT_TRUE(set && set->lights.at(0).shadow) << error;
        const ShadowExport& e = *set->lights[0].shadow;
        const nlohmann::json json = nlohmann::json::parse(exportSnippet(e, ExportFormat::Json));
        const nlohmann::json& moments = json["technique"]["moments"];
        ASSERT_EQ(moments["minFilter"], "linear-mipmap-linear");
        const int levels = moments["levels"];

        std::vector<PixelProbeReport> reports;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) reports.push_back(probe.at(x, y));
        const auto at = [&](int x, int glRow) -> const PixelProbeReport& {
            return reports[std::size_t(kHeight - 1 - glRow) * kWidth + std::size_t(x)];
        };
        const auto sameTriangle = [](const PixelProbeReport& a, const PixelProbeReport& b) {
            return a.ok && b.ok && a.instance == b.instance && a.triangle == b.triangle;
        };
        std::vector<Point> points;
        double minLevel = 1e9, maxLevel = -1e9;
        for (int glRow = 0; glRow < kHeight; ++glRow)
            for (int x = 0; x < kWidth; ++x) {
                const PixelProbeReport& r = at(x, glRow);
                const PixelProbeReport &left = at(x & ~1, glRow), &right = at(x | 1, glRow);
                const PixelProbeReport &below = at(x, glRow & ~1), &above = at(x, glRow | 1);
                if (!r.ok || !sameTriangle(left, right) || !sameTriangle(below, above) || !sameTriangle(r, left) ||
                    !sameTriangle(r, below))
                    continue;
                Point p{glm::vec3(r.world - e.renderOrigin), glm::vec3(r.shadingNormal),
                        glm::vec2(float(x) + 0.5f, float(glRow) + 0.5f), float(r.shadowGpu)};
                p.dx = glm::vec3(right.world - left.world);
                p.dy = glm::vec3(above.world - below.world);
                points.push_back(p);
                minLevel = std::min(minLevel, r.momentLevel);
                maxLevel = std::max(maxLevel, r.momentLevel);
            }
        ASSERT_GT(points.size(), 5000u);
        EXPECT_GT(maxLevel, 1.0) << "the footprints reach coarser levels";

        // ShadowLab's levels in one 2D array of one layer, sampled as the export says.
        const GLenum format = momentInternalFormat(filterTechnique(kind), 32);
        gl::Texture map = gl::createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(map.id(), levels, format, resolution, resolution, 1);
        for (int level = 0; level < levels; ++level) {
            const int size = std::max(resolution >> level, 1);
            const std::vector<glm::vec4> stored = renderer.viewMoments({0, ShadowViewKind::Single, 0}, 0, 0, size, size, level);
            ASSERT_EQ(stored.size(), std::size_t(size) * size) << "level " << level;
            glTextureSubImage3D(map.id(), level, 0, 0, 0, size, size, 1, GL_RGBA, GL_FLOAT, stored.data());
        }
        gl::Sampler sampler = gl::createSampler();
        const GLint wrap = wrapOf(json["sampler"]["addressMode"]);
        const std::vector<float> border = moments["border"];
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_S, wrap);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, wrap);
        glSamplerParameterfv(sampler.id(), GL_TEXTURE_BORDER_COLOR, border.data());
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glBindTextureUnit(0, map.id());
        glBindSampler(0, sampler.id());
        const std::vector<float> exported =
            exportedShadow(json["technique"]["lookupGlsl"], points, false, {{"uMaps2D[0]", 0}}, /*derivatives=*/true);
        glBindSampler(0, 0);
        char levelText[64];
        std::snprintf(levelText, sizeof levelText, ", levels %.2f..%.2f of %d", minLevel, maxLevel, levels);
        expectMainPassShadow(name, "mips lookup", levelText, exported, points);
    }
}

}  // namespace shadowlab::test
