// Issue 20, "bias per cascade keeps its meaning": the frame's bias report lists every cascade of a cascaded light,
// each in depth units, world units and texels of its own texel; and the export of a cascaded light (each cascade's
// matrix, split and bias, the selection as ShadowLab's own GLSL) compiles as a GLSL fragment shader.
#include "gl_fixture.h"

#include "export/shadow_export.h"
#include "export/shadow_shader_code.h"
#include "frame/camera.h"
#include "gl/program.h"

namespace shadowlab::test {
namespace {

class CascadeBiasAndExport : public GlTest {};

// The textbook from near the floor across it, 3 cascades (as tests/accuracy/test_cascades_accuracy.cpp sees it).
Settings cascadedTextbook() {
    Settings s = loadShippedPreset("default");
    LightSettings& sun = s.lights[0];
    sun.projection.fit = ProjectionFit::Cascades;
    sun.projection.cascadeCount = 3;
    sun.projection.shadowDistance = 30.0f;
    sun.projection.splitLambda = 0.6f;
    sun.projection.blendBand = 0.1f;
    sun.shadow.resolution = 512;
    sun.shadow.depthBias = 2.0f;
    sun.shadow.normalOffset = 0.5f;
    s.camera.autoFrame = false;
    s.camera.position = {-4.0, 1.2, 9.0};
    s.camera.target = {1.0, 0.3, -3.0};
    return s;
}

TEST_F(CascadeBiasAndExport, TheBiasReportListsEveryCascadeInItsOwnTexels) {
    const Scene scene = loadBuiltin("textbook");
    const Settings s = cascadedTextbook();
    Renderer renderer;
    const View view = renderView(renderer, scene, s, 160, 90);
    ASSERT_TRUE(view.stats.ok) << view.stats.error;
    const std::vector<ShadowView> cascades = frameViewsOf(view.stats, 0);
    ASSERT_EQ(cascades.size(), 3u);
    ASSERT_EQ(view.stats.viewBias.size(), 3u) << "one bias row per cascade";
    for (std::size_t c = 0; c < 3; ++c) {
        const FrameStats::ViewBias& row = view.stats.viewBias[c];
        EXPECT_EQ(row.name, "light 0 cascade:" + std::to_string(c));
        const BiasReport& b = row.bias;
        ASSERT_TRUE(b.valid) << row.name << " has receivers";
        const double texel = cascades[c].space.texelWorldSize;
        EXPECT_DOUBLE_EQ(b.texelWorldSize, texel) << row.name;
        EXPECT_DOUBLE_EQ(b.normalOffsetWorld, 0.5 * texel) << row.name << ": the normal offset in its own texels";
        // Each term's texels are its world size over this cascade's texel.
        for (const BiasTerm* t : {&b.constantNear, &b.slope, &b.total})
            EXPECT_NEAR(t->texels, t->world / texel, 1e-9 * std::max(1.0, t->texels)) << row.name;
        if (c > 0) {
            EXPECT_GT(texel, cascades[c - 1].space.texelWorldSize) << "farther cascades have coarser texels";
            // The depth spans the same sphere along the light in every cascade: DepthBias x r keeps its world size
            // (within D32F's exponent step), while its size in texels shrinks with the coarser texel.
            const BiasReport& prev = view.stats.viewBias[c - 1].bias;
            EXPECT_NEAR(b.constantNear.world / prev.constantNear.world, 1.0, 1.01) << row.name;
        }
    }
    EXPECT_EQ(view.stats.bias.texelWorldSize, view.stats.viewBias[0].bias.texelWorldSize);
}

TEST_F(CascadeBiasAndExport, ACascadedLightsExportCompilesAsGlsl) {
    const Scene scene = loadBuiltin("textbook");
    const Settings s = cascadedTextbook();
    const Camera camera = cameraFor(s.camera, scene, 16.0 / 9.0);
    const ViewCamera viewCamera = viewCameraOf(camera, 16.0 / 9.0, renderOriginOf(scene.bounds));
    std::string error;
    const std::optional<ShadowExportSet> set = exportForScene(s, scene, "builtin:textbook", 0, error, &viewCamera);
    ASSERT_TRUE(set) << error;
    const ShadowExport& e = *set->lights.at(0).shadow;
    ASSERT_TRUE(e.cascaded);
    ASSERT_EQ(e.views.size(), 3u);
    for (bool receiverPlane : {true, false}) {
        ShadowExport variant = e;
        variant.receiverPlane = receiverPlane;
        const std::string code = shadowShaderCode(variant, shaderTargetFor(ExportFormat::GL, false));
        const std::string args = receiverPlane ? ", dFdx(worldPos), dFdy(worldPos)" : "";
        const std::string fragment =
            "#version 450\n" + code +
            "layout(binding = 0) uniform sampler2DShadow cascadeMaps[3];\n"
            "uniform mat4 cascadeMatrices[3];\n"
            "in vec3 worldPos;\nin vec3 normal;\nout vec4 colour;\n"
            "float cascadeS(int c) {\n"
            "    if (c == 0) return light0Shadow(cascadeMaps[0], cascadeMatrices[0], LIGHT0_CASCADE_TEXEL_WORLD[0], worldPos, normal" + args + ");\n"
            "    if (c == 1) return light0Shadow(cascadeMaps[1], cascadeMatrices[1], LIGHT0_CASCADE_TEXEL_WORLD[1], worldPos, normal" + args + ");\n"
            "    return light0Shadow(cascadeMaps[2], cascadeMatrices[2], LIGHT0_CASCADE_TEXEL_WORLD[2], worldPos, normal" + args + ");\n"
            "}\n"
            "void main() {\n"
            "    CascadeChoice choice = light0Cascade(worldPos);\n"
            "    float s = choice.view < 0 ? 1.0 : cascadeS(choice.view);\n"
            "    if (choice.next >= 0) s = mix(s, cascadeS(choice.next), choice.weight);\n"
            "    colour = vec4(s);\n"
            "}\n";
        const GLuint shader = glCreateShader(GL_FRAGMENT_SHADER);
        const char* text = fragment.c_str();
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        GLint ok = GL_FALSE;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        std::string log(4096, '\0');
        GLsizei length = 0;
        glGetShaderInfoLog(shader, GLsizei(log.size()), &length, log.data());
        glDeleteShader(shader);
        EXPECT_EQ(ok, GL_TRUE) << log.substr(0, std::size_t(length)) << "\n" << fragment;
    }
}

// A cascaded sun and a point light exported together: both lights' code prints the renderer's view_select.glsl (the
// cascade selection, the point light's cube_face_depth.glsl includes it), each file inside its own include guard, so
// the two compile in one shader (a second definition of cubeFaceOf would not).
TEST_F(CascadeBiasAndExport, ACascadedAndAPointLightsCodeCompileInOneShader) {
    const Scene scene = loadBuiltin("textbook");
    Settings s = cascadedTextbook();
    LightSettings point = s.lights[0];
    point.type = LightType::Point;
    point.position = {2.0f, 7.0f, 3.0f};
    point.projection.fit = ProjectionFit::Scene;
    s.lights.push_back(point);
    const Camera camera = cameraFor(s.camera, scene, 16.0 / 9.0);
    const ViewCamera viewCamera = viewCameraOf(camera, 16.0 / 9.0, renderOriginOf(scene.bounds));
    std::string error;
    const std::optional<ShadowExportSet> set = exportForScene(s, scene, "builtin:textbook", std::nullopt, error, &viewCamera);
    ASSERT_TRUE(set) << error;
    ASSERT_EQ(set->lights.size(), 2u);
    ASSERT_TRUE(set->lights[0].shadow && set->lights[0].shadow->cascaded);
    ASSERT_TRUE(set->lights[1].shadow);
    std::string code;
    for (const LightExport& l : set->lights) code += shadowShaderCode(*l.shadow, shaderTargetFor(ExportFormat::GL, false));
    const std::string fragment =
        "#version 450\n" + code +
        "layout(binding = 0) uniform sampler2DShadow sunMap;\nlayout(binding = 1) uniform samplerCubeShadow pointMap;\n"
        "uniform mat4 sunMatrix;\nin vec3 worldPos;\nin vec3 normal;\nout vec4 colour;\n"
        "void main() {\n"
        "    CascadeChoice choice = light0Cascade(worldPos);\n"
        "    float sun = light0Shadow(sunMap, sunMatrix, LIGHT0_CASCADE_TEXEL_WORLD[0], worldPos, normal, dFdx(worldPos), dFdy(worldPos));\n"
        "    colour = vec4(choice.weight * sun * light1Shadow(pointMap, worldPos, normal));\n"
        "}\n";
    const GLuint shader = glCreateShader(GL_FRAGMENT_SHADER);
    const char* text = fragment.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    std::string log(4096, '\0');
    GLsizei length = 0;
    glGetShaderInfoLog(shader, GLsizei(log.size()), &length, log.data());
    glDeleteShader(shader);
    EXPECT_EQ(ok, GL_TRUE) << log.substr(0, std::size_t(length)) << "\n" << fragment;
}

}  // namespace
}  // namespace shadowlab::test
