// Numerically hard cases from ../shared/HARD_CASES.md that the core renderer must already survive.
#include "gl_fixture.h"

#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"

#include <glm/ext/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <optional>

namespace shadowlab::test {
namespace {

class HardCases : public GlTest {};

long darkScenePixels(const View& view) { return view.countScenePixels([](int red) { return red < 128; }); }

TEST_F(HardCases, EveryDepthFormatRendersTheSameShadows) {
    // Case 4: D16 / D24 / D32F. On a 20-unit scene every format resolves the cube's shadow.
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    for (DepthFormat format : {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F}) {
        Settings s = topDownShadowView(loadShippedPreset("default"));
        s.lights[0].shadow.format = format;
        s.lights[0].shadow.depthBias = format == DepthFormat::D16 ? 4.0f : 2.0f;
        const View view = renderView(renderer, scene, s, 320, 320);
        EXPECT_EQ(view.stats.shadowMapFormat, format);
        EXPECT_LT(view.meanRedAround({-1.4, 0.0, -1.3}, 2), 20.0) << depthFormatName(format);
        EXPECT_GT(view.meanRedAround({5.0, 0.0, 5.0}, 2), 235.0) << depthFormatName(format);
    }
}

// A horizontal quad (y = height, x and z in [-half, half]), facing up.
Mesh horizontalQuad(const std::string& name, float height, float half, int material) {
    Mesh m;
    m.name = name;
    m.positions = {{-half, height, -half}, {-half, height, half}, {half, height, half}, {half, height, -half}};
    m.normals.assign(4, glm::vec3(0, 1, 0));
    m.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    m.indices = {0, 1, 2, 0, 2, 3};
    m.material = material;
    return m;
}

TEST_F(HardCases, SlopeBiasClampKeepsTheShadowAttachedAtGrazingLight) {
    // Case 2: a caster at grazing light gets a huge slope-scaled bias that can push it behind its receiver.
    // DepthBiasClamp (glPolygonOffsetClamp) caps it.
    Renderer renderer;
    if (!renderer.glInfo().polygonOffsetClamp) GTEST_SKIP() << "no glPolygonOffsetClamp on this GL";
    Scene scene;
    scene.name = "floating-card";
    Material twoSided;
    twoSided.doubleSided = true;
    scene.materials.push_back(twoSided);
    scene.meshes.push_back(horizontalQuad("floor", 0.0f, 10.0f, -1));
    scene.meshes.push_back(horizontalQuad("card", 1.0f, 1.0f, 0));  // a single-sided card, drawn two-sided
    scene.instances = {{0, glm::mat4(1.0f)}, {1, glm::mat4(1.0f)}};
    scene.computeBounds();

    Settings s = topDownShadowView(loadShippedPreset("default"));
    s.lights[0].direction = glm::vec3(-1.0f, -0.2f, 0.0f);  // 78.7 degrees from vertical: the card's shadow is 5 units off
    s.lights[0].shadow.slopeScaledDepthBias = 100.0f;             // ~7 world units on the card: more than its 5.1 to the floor
    s.lights[0].shadow.depthBias = 0.0f;
    s.lights[0].shadow.normalOffset = 0.0f;
    s.lights[0].shadow.depthBiasClamp = 0.0f;
    const View unclamped = renderView(renderer, scene, s, 400, 400);
    s.lights[0].shadow.depthBiasClamp = 0.01f;  // 0.28 world units over the 28-unit fitted depth range: ends the floor acne
    const View clamped = renderView(renderer, scene, s, 400, 400);
    saveView(unclamped, "grazing-card-unclamped");
    saveView(clamped, "grazing-card-clamped");
    const glm::dvec3 shadowCentre(-5.0, 0.0, 0.0);
    EXPECT_LT(clamped.meanRedAround(shadowCentre, 2), 20.0) << "the clamped bias keeps the card's shadow";
    EXPECT_GT(unclamped.meanRedAround(shadowCentre, 2), 235.0) << "without a clamp the shadow vanishes (case 2)";
    EXPECT_GT(clamped.meanRedAround({5.0, 0.0, 5.0}, 3), 235.0) << "the clamp still leaves the floor enough bias";
}

TEST_F(HardCases, DepthClampKeepsCastersBeforeTheNearPlane) {
    // Case 12 (pancaking): a near plane fitted tightly to the receivers cuts the cube's top face off. With
    // GL_DEPTH_CLAMP the cube still casts; without it its shadow on the floor beside it is gone.
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Settings s = topDownShadowView(loadShippedPreset("default"));
    // Back culling: the map holds only the cube's light-facing top, which the near plane clips (with cull mode none
    // the bottom face still casts, clamp or not).
    s.lights[0].shadow.cullMode = CullMode::Back;
    const View fitted = renderView(renderer, scene, s, 320, 320);
    const double eyeToCentre = 0.5 * fitted.stats.light.farPlane;  // the auto-fit eye sits one radius before the centre
    s.lights[0].projection.autoFit = false;
    s.lights[0].projection.orthoSize = float(fitted.stats.light.orthoSize);
    // The cube's top face lies within 1 unit of the scene centre along the light; the floor beside it, 2.3 beyond.
    s.lights[0].projection.nearPlane = float(eyeToCentre + 0.5);
    s.lights[0].projection.farPlane = float(2.0 * eyeToCentre);
    s.lights[0].projection.depthClamp = true;
    const View clamped = renderView(renderer, scene, s, 320, 320);
    s.lights[0].projection.depthClamp = false;
    const View unclamped = renderView(renderer, scene, s, 320, 320);
    EXPECT_LT(clamped.meanRedAround({-1.4, 0.0, -1.3}, 2), 20.0) << "depth clamp: the cube still casts";
    EXPECT_GT(unclamped.meanRedAround({-1.4, 0.0, -1.3}, 2), 235.0) << "without it, the clipped top casts nothing";
}

TEST_F(HardCases, NonFiniteVerticesNeitherBreakTheFitNorTheMap) {
    // Case 16: a mesh with an infinite vertex beside a normal scene. Fitting ignores it; the frame stays valid.
    Renderer renderer;
    Scene scene = loadBuiltin("textbook");
    Mesh broken;
    broken.name = "broken";
    const float inf = std::numeric_limits<float>::infinity();
    broken.positions = {{0, 5, 0}, {inf, 5, 0}, {0, 5, 1}};
    broken.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    broken.indices = {0, 1, 2};
    scene.meshes.push_back(broken);
    scene.instances.push_back({int(scene.meshes.size() - 1), glm::mat4(1.0f)});
    const Bounds before = loadBuiltin("textbook").bounds;
    scene.computeBounds();
    EXPECT_EQ(scene.bounds.min, glm::min(before.min, glm::vec3(0, 5, 0)));
    EXPECT_TRUE(std::isfinite(scene.bounds.radius()));
    const View view = renderView(renderer, scene, topDownShadowView(loadShippedPreset("default")), 200, 200);
    EXPECT_TRUE(allFinite(view.stats.light.viewProjection()));
    EXPECT_LT(view.meanRedAround({-1.4, 0.0, -1.3}, 1), 20.0);
}

TEST_F(HardCases, LargeWorldOffsetGivesTheSamePicture) {
    // Case 3: the whole scene moved 1e5 on x and z. Matrices are built relative to the scene's centre in double,
    // so the shadow mask must not change beyond a sliver of edge pixels.
    Renderer renderer;
    const Scene scene = loadBuiltin("textbook");
    Scene moved = scene;
    const glm::vec3 offset(1e5f, 0.0f, 1e5f);
    for (Instance& instance : moved.instances) instance.transform = glm::translate(glm::mat4(1.0f), offset) * instance.transform;
    moved.computeBounds();
    Settings s = loadShippedPreset("default");
    s.view = ViewMode::Shadow;
    const View a = renderView(renderer, scene, s, 320, 240);
    const View b = renderView(renderer, moved, s, 320, 240);
    long differ = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) differ += std::abs(int(a.rgba[i]) - int(b.rgba[i])) > 64;
    EXPECT_LT(differ, long(a.rgba.size() / 4 / 200)) << "more than 0.5% of pixels changed";
    EXPECT_GT(darkScenePixels(b), 300);
}

TEST_F(HardCases, SceneLightFromGltfIsUsedWhenAsked) {
    Renderer renderer;
    Scene scene = loadBuiltin("textbook");
    SceneLight sun;
    sun.type = SceneLightType::Directional;
    sun.direction = glm::vec3(0.4f, -1.0f, 0.3f);  // the mirror image of the default: shadows fall to +x, +z
    scene.lights.push_back(sun);
    Settings s = topDownShadowView(loadShippedPreset("default"));
    s.useSceneLights = true;
    const View view = renderView(renderer, scene, s, 320, 320);
    EXPECT_LT(view.meanRedAround({1.4, 0.0, 1.3}, 2), 20.0) << "shadow on the +x,+z side";
    EXPECT_GT(view.meanRedAround({-1.4, 0.0, -1.3}, 2), 235.0) << "the default light's shadow side is lit";
}

}  // namespace
}  // namespace shadowlab::test

namespace shadowlab::test {
namespace {

// Reads back every float uniform of the program the main pass used last: all must be finite (HARD_CASES 14).
std::vector<std::string> nonFiniteUniforms() {
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    std::vector<std::string> bad;
    if (program == 0) return {"no program bound"};
    GLint count = 0;
    glGetProgramiv(GLuint(program), GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char name[128];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(GLuint(program), GLuint(i), sizeof name, nullptr, &size, &type, name);
        int components = 0;
        switch (type) {
            case GL_FLOAT: components = 1; break;
            case GL_FLOAT_VEC2: components = 2; break;
            case GL_FLOAT_VEC3: components = 3; break;
            case GL_FLOAT_VEC4: components = 4; break;
            case GL_FLOAT_MAT3: components = 9; break;
            case GL_FLOAT_MAT4: components = 16; break;
            default: continue;
        }
        const GLint location = glGetUniformLocation(GLuint(program), name);
        if (location < 0) continue;  // a member of the Lights block: checked below, in the buffer
        float values[16] = {};
        glGetUniformfv(GLuint(program), location, values);
        for (int c = 0; c < components; ++c)
            if (!std::isfinite(values[c])) bad.push_back(name);
    }
    // The per-light data (matrices, positions, cone, texel sizes) lives in the uniform buffer at binding 0.
    GLint buffer = 0, bytes = 0;
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 0, &buffer);
    if (buffer != 0) {
        glGetNamedBufferParameteriv(GLuint(buffer), GL_BUFFER_SIZE, &bytes);
        std::vector<float> block(std::size_t(bytes) / sizeof(float));
        glGetNamedBufferSubData(GLuint(buffer), 0, GLsizeiptr(block.size() * sizeof(float)), block.data());
        for (std::size_t i = 0; i < block.size(); ++i)
            if (!std::isfinite(block[i])) bad.push_back("Lights block float " + std::to_string(i));
    }
    return bad;
}

TEST_F(HardCases, NoNonFiniteUniformReachesTheGpuForExtremeButValidSettings) {
    Renderer renderer;
    const Scene textbook = loadBuiltin("textbook");
    Scene zeroScale = textbook;
    zeroScale.instances[1].transform = glm::scale(glm::mat4(1.0f), glm::vec3(0.0f));  // no inverse for normals
    zeroScale.computeBounds();
    struct Case {
        const char* name;
        const Scene* scene;
        void (*tweak)(Settings&);
    };
    const Case cases[] = {
        {"straight down", &textbook, [](Settings& s) { s.lights[0].direction = {0, -1, 0}; }},
        {"straight up", &textbook, [](Settings& s) { s.lights[0].direction = {0, 1, 0}; }},
        {"pole tilt 1e-7", &textbook, [](Settings& s) { s.lights[0].direction = {1e-7f, -1, 0}; }},
        {"spot 170 degrees", &textbook,
         [](Settings& s) {
             s.lights[0].type = LightType::Spot;
             s.lights[0].spotConeDeg = 170.0f;
             s.lights[0].direction = {0, -1, 0};
         }},
        {"spot inside the scene", &textbook,
         [](Settings& s) {
             s.lights[0].type = LightType::Spot;
             s.lights[0].position = {0, 1, 0};  // inside the cube
             s.lights[0].direction = {1, -0.2f, 0};
         }},
        {"tiny ortho volume", &textbook,
         [](Settings& s) {
             s.lights[0].projection.autoFit = false;
             s.lights[0].projection.orthoSize = 1e-3f;
             s.lights[0].projection.nearPlane = 1e-4f;
             s.lights[0].projection.farPlane = 1e-3f;
         }},
        {"huge normal offset, D16", &textbook,
         [](Settings& s) {
             s.lights[0].shadow.normalOffset = 16.0f;
             s.lights[0].shadow.format = DepthFormat::D16;
             s.lights[0].shadow.resolution = 16;
         }},
        {"zero-scale instance", &zeroScale, [](Settings&) {}},
    };
    for (const Case& c : cases) {
        Settings s = loadShippedPreset("default");
        c.tweak(s);
        const View view = renderView(renderer, *c.scene, s, 64, 64);
        ASSERT_TRUE(view.stats.ok) << c.name << ": " << view.stats.error;
        EXPECT_TRUE(allFinite(view.stats.light.viewProjection())) << c.name;
        const std::vector<std::string> bad = nonFiniteUniforms();
        EXPECT_TRUE(bad.empty()) << c.name << ": non-finite uniform " << (bad.empty() ? "" : bad[0]);
    }
}

}  // namespace
}  // namespace shadowlab::test

namespace shadowlab::test {
namespace {

TEST_F(HardCases, LightSweptAcrossStraightDownStaysFiniteAndStable) {
    // HARD_CASES 1: L(t) = (sin t, -cos t, 0) for t in [-1e-3, 1e-3] over AlphaBlendModeTest. The textbook lookAt
    // gives NaN at t = 0 and flips the map 180 degrees across it; ours must change the picture only as much as the
    // light's motion does.
    const std::string path = std::string(SHADOWLAB_SOURCE_DIR) +
                             "/../shared/scenes/AlphaBlendModeTest/AlphaBlendModeTest.gltf";
    SceneLoadResult loaded = loadScene(path);
    if (!loaded.scene) GTEST_SKIP() << loaded.error;
    const Scene& scene = *loaded.scene;
    Renderer renderer;
    Settings s = loadShippedPreset("default");
    s.view = ViewMode::Shadow;
    std::optional<View> previous;
    for (int step = -10; step <= 10; ++step) {
        const double t = step * 1e-4;
        s.lights[0].direction = glm::vec3(float(std::sin(t)), float(-std::cos(t)), 0.0f);
        const View view = renderView(renderer, scene, s, 200, 150);
        ASSERT_TRUE(allFinite(view.stats.light.viewProjection())) << "t=" << t;
        if (previous) {
            long changed = 0, total = 0;
            for (std::size_t i = 0; i * 4 < view.rgba.size(); ++i) {
                if (!view.isGreyScene(i)) continue;
                ++total;
                changed += std::abs(int(view.rgba[i * 4]) - int(previous->rgba[i * 4])) > 64;
            }
            EXPECT_LT(double(changed), 0.002 * double(total)) << "flicker between adjacent t at t=" << t;
        }
        previous = view;
    }
}

}  // namespace
}  // namespace shadowlab::test
