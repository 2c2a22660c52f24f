// A cache error (issue 22): a caster the user flags static (casters.static) that an animation moves stays in a
// cachedStatic light's cached depth where it was. Measured against the exact reference at the same animation time,
// the frame is wrong where the Spinner's shadow was and where it is now, and the frame warns naming the node; the
// same motion with the Spinner dynamic (its default: "Spin" moves it) is as right as a full re-render.
#include "gl_fixture.h"
#include "reference_fixture.h"
#include "scene/gltf_loader.h"
#include "scene/scene_animation.h"
#include "settings/settings_fields.h"

#include <algorithm>

namespace shadowlab::test {
namespace {

class StaticCacheError : public GlTest {};

constexpr int kSize = 240;

Settings spinSettings(const char* update, bool spinnerFlaggedStatic) {
    Settings s = topDownShadowView(loadShippedPreset("default"));
    for (const char* kv : {"animation.play=Spin", "lights.0.direction=-0.3,-1,-0.2", "lights.0.shadow.resolution=1024"})
        EXPECT_EQ(applySettingOverride(s, kv), "") << kv;
    EXPECT_EQ(applySettingOverride(s, std::string("lights.0.shadow.update=") + update), "");
    if (spinnerFlaggedStatic) EXPECT_EQ(applySettingOverride(s, "casters.static=Spinner"), "");
    return s;
}

// Measures the scene posed at 0 s and then at `time` with one meter (its renderer keeps its maps between the two,
// as a playing editor does); the second report.
AccuracyReport measureAfterMotion(const Settings& settings, float time, const std::string& name) {
    SceneLoadResult loaded = loadGltfScene(std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/animated_boxes.gltf");
    EXPECT_TRUE(loaded.scene) << loaded.error;
    Scene& scene = *loaded.scene;
    AccuracyMeter meter;
    AccuracyReport r;
    for (float t : {0.0f, time}) {
        Settings s = settings;
        s.animation.time = t;
        EXPECT_EQ(poseScene(scene, s.animation), "");
        const Camera camera = cameraFor(s.camera, scene, 1.0);
        r = meter.measure(scene, s, camera, kSize, kSize);
        EXPECT_TRUE(r.ok) << r.error;
    }
    saveOverlay(r, name);
    return r;
}

bool warnsNaming(const AccuracyReport& r, const std::string& node) {
    return std::any_of(r.warnings.begin(), r.warnings.end(), [&](const std::string& w) {
        return w.find("casters.static") != std::string::npos && w.find(node) != std::string::npos;
    });
}

TEST_F(StaticCacheError, AStaticFlaggedCasterThatMovesIsACacheErrorWithAWarningNamingIt) {
    const AccuracyReport full = measureAfterMotion(spinSettings("onChange", false), 1.0f, "spin-full");
    const AccuracyReport cached = measureAfterMotion(spinSettings("cachedStatic", false), 1.0f, "spin-cached");
    const AccuracyReport stale = measureAfterMotion(spinSettings("cachedStatic", true), 1.0f, "spin-static-flagged");
    std::printf("wrong pixels against the reference at t = 1 s: full re-render %zu (%.3f %%, mean error %.4f), "
                "cachedStatic %zu (%.3f %%), Spinner flagged static %zu (%.3f %%, mean error %.4f)\n",
                full.counts.wrong, full.wrongPercent, full.meanError, cached.counts.wrong, cached.wrongPercent,
                stale.counts.wrong, stale.wrongPercent, stale.meanError);
    EXPECT_EQ(cached.counts.wrong, full.counts.wrong);  // the cache itself costs nothing
    EXPECT_FALSE(warnsNaming(cached, "Spinner"));
    // The Spinner turned 90 degrees (a 3 x 0.5 bar): its old shadow stays, its new one is missing.
    EXPECT_GT(stale.counts.wrong, full.counts.wrong + 100);
    EXPECT_GT(stale.meanError, full.meanError);
    EXPECT_TRUE(warnsNaming(stale, "Spinner")) << (stale.warnings.empty() ? "no warning" : stale.warnings.front());
}

}  // namespace
}  // namespace shadowlab::test
