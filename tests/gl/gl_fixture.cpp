#include "gl_fixture.h"

#include "scene/builtin_scenes.h"
#include "settings/preset_io.h"

#include <algorithm>

namespace shadowlab::test {

HeadlessContext& sharedContext() {
    static HeadlessContext context(/*debug=*/true);
    static bool debugInstalled = (gl::enableDebugOutput(), true);
    (void)debugInstalled;
    return context;
}

void GlTest::SetUp() {
    sharedContext().makeCurrent();
    gl::takeDebugErrors();
    gl::drainErrors();
}

void GlTest::TearDown() {
    const std::vector<std::string> errors = gl::takeDebugErrors();
    for (const std::string& e : errors) ADD_FAILURE() << "GL debug error: " << e;
    const std::string drained = gl::drainErrors();
    EXPECT_TRUE(drained.empty()) << "glGetError: " << drained;
}

int View::red(int x, int yDown) const {
    x = std::clamp(x, 0, width - 1);
    yDown = std::clamp(yDown, 0, height - 1);
    const int row = height - 1 - yDown;
    return rgba[(std::size_t(row) * width + x) * 4];
}

int View::redAt(const glm::dvec3& world) const {
    double px = 0, py = 0;
    if (!projectToPixel(stats, world, width, height, px, py)) return -1;
    return red(int(px), int(py));
}

double View::meanRedAround(const glm::dvec3& world, int r) const {
    double px = 0, py = 0;
    if (!projectToPixel(stats, world, width, height, px, py)) return -1;
    double sum = 0;
    int n = 0;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx, ++n) sum += red(int(px) + dx, int(py) + dy);
    return sum / n;
}

View renderView(Renderer& renderer, const Scene& scene, const Settings& settings, int width, int height) {
    RenderTarget target;
    EXPECT_EQ(target.resize(width, height), "");
    View view;
    view.width = width;
    view.height = height;
    view.stats = renderer.render(scene, settings, cameraFor(settings.camera, scene, double(width) / height), target);
    EXPECT_TRUE(view.stats.ok) << view.stats.error;
    view.rgba = target.readColor();
    return view;
}

std::string saveView(const View& view, const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(SHADOWLAB_TEST_OUTPUT) / "gl";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / (name + ".png")).string();
    EXPECT_EQ(writePng(path, view.width, view.height, 4, view.rgba.data(), true), "");
    return path;
}

Settings topDownShadowView(Settings s) {
    s.camera.autoFrame = false;
    s.camera.position = glm::vec3(0.0f, 30.0f, 0.0f);
    s.camera.target = glm::vec3(0.0f);
    s.camera.fovYDeg = 45.0f;
    s.view = ViewMode::Shadow;
    return s;
}

Scene loadBuiltin(const std::string& name) {
    std::optional<Scene> scene = makeBuiltinScene(name);
    if (!scene) throw std::runtime_error("no builtin scene " + name);
    return std::move(*scene);
}

Settings loadShippedPreset(const std::string& name) {
    const std::string path = std::string(SHADOWLAB_SOURCE_DIR) + "/presets/" + name + ".json";
    PresetLoadResult result = loadPresetFile(path);
    if (!result.settings) throw std::runtime_error("preset " + path + " did not load");
    return *result.settings;
}

Settings zeroBias(Settings settings) {
    ShadowMapSettings& shadow = settings.lights[0].shadow;
    shadow.depthBias = 0.0f;
    shadow.slopeScaledDepthBias = 0.0f;
    shadow.normalOffset = 0.0f;
    return settings;
}

}  // namespace shadowlab::test
