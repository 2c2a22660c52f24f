// The exported lookup of a moments technique (VSM, EVSM4, MSM) and of PCSS renders ShadowLab's shadow: at every
// surface pixel of the textbook view, the exported GLSL (from the JSON export: the lookup, the moments' format and
// border, nothing from ShadowLab's own objects but the stored maps) computes, in a GL fragment shader at that pixel,
// the shadow factor S of the pixel's surface point; ShadowLab's main pass wrote S there (the pixel probe reads it,
// with the point and normal from its G-buffer). They must agree within a stated bound.
#include "export/export_snippets.h"
#include "gl/gl.h"
#include "gl/gl_objects.h"
#include "gl/program.h"
#include "gl_fixture.h"
#include "probe/pixel_probe.h"
#include "shading/filters/filter_technique.h"

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
};

// The exported lookup, evaluated by a point drawn at each pixel's centre (gl_FragCoord as the main pass had it, which
// PCSS's per-pixel rotation reads). Returns S per point.
std::vector<float> exportedShadow(const std::string& lookup, const std::vector<Point>& points, bool cube,
                                  const std::vector<std::pair<const char*, int>>& units) {
    const std::string vertex =
        "#version 450 core\n"
        "layout(location = 0) in vec3 aWorld;\nlayout(location = 1) in vec3 aNormal;\nlayout(location = 2) in vec2 aPixel;\n"
        "uniform vec2 uSize;\nout vec3 vWorld;\nout vec3 vNormal;\n"
        "void main() { gl_Position = vec4(aPixel / uSize * 2.0 - 1.0, 0.0, 1.0); gl_PointSize = 1.0; vWorld = aWorld; "
        "vNormal = aNormal; }\n";
    const std::string fragment = "#version 450 core\n" + lookup +
                                 "in vec3 vWorld;\nin vec3 vNormal;\nlayout(location = 0) out float outShadow;\n"
                                 "void main() { outShadow = light0Shadow(" + std::string(cube ? "" : "0, ") +
                                 "vWorld, normalize(vNormal)); }\n";
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
        for (float v : {p.world.x, p.world.y, p.world.z, p.normal.x, p.normal.y, p.normal.z, p.pixel.x, p.pixel.y})
            attributes.push_back(v);
    gl::Buffer buffer = gl::createBuffer();
    glNamedBufferData(buffer.id(), GLsizeiptr(attributes.size() * sizeof(float)), attributes.data(), GL_STATIC_DRAW);
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    glVertexArrayVertexBuffer(vao, 0, buffer.id(), 0, 8 * sizeof(float));
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, a == 2 ? 2 : 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
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
        double maxDiff = 0.0, sumDiff = 0.0;
        std::size_t over = 0, partial = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const double d = std::abs(double(exported[i]) - double(points[i].shadowLab));
            maxDiff = std::max(maxDiff, d);
            sumDiff += d;
            over += d > 1e-3;
            partial += points[i].shadowLab > 0.0f && points[i].shadowLab < 1.0f;
        }
        std::printf("[ export ] %s: exported lookup vs ShadowLab's main pass at %zu surface pixels (%zu partly lit): "
                    "max |dS| %.3g, mean %.3g, %zu pixels over 1e-3\n",
                    name.c_str(), points.size(), partial, maxDiff, sumDiff / double(points.size()), over);
        // Measured (llvmpipe): VSM, EVSM4, PCSS none over 1e-3 (max 1.5e-4); MSM 11-18 pixels (0.2-0.3 %, max 0.018):
        // Hamburger's bound is ill-conditioned near the caster, so the G-buffer's point (the probe's) against the main
        // pass's interpolated one moves it there. Bound: 0.5 % of the pixels, mean 1e-4.
        EXPECT_GT(partial, 50u) << "soft edges are compared, not only 0 and 1";
        EXPECT_LE(double(over), 0.005 * double(points.size())) << "pixels whose exported S differs by more than 1e-3";
        EXPECT_LT(sumDiff / double(points.size()), 1e-4);
    }
}

}  // namespace shadowlab::test
