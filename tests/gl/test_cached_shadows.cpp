// Moving scenes (issue 22, "Only what moved"): tests/data/scenes/animated_boxes.gltf playing "Spin" (only the
// Spinner moves) under a point light's six faces. A frame re-renders only the faces whose volume held the Spinner
// before or holds it now, a still frame renders none, and a cachedStatic light draws only the Spinner into a face,
// over a copy of its cached static depth, with maps texel for texel those of a full re-render.
#include "gl_fixture.h"

#include "scene/gltf_loader.h"
#include "scene/scene_animation.h"
#include "settings/settings_fields.h"
#include "shadow/shadow_pass.h"

#include <algorithm>

namespace shadowlab::test {
namespace {

class CachedShadows : public GlTest {};

Scene spinningBoxes() {
    SceneLoadResult r = loadGltfScene(std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/animated_boxes.gltf");
    EXPECT_TRUE(r.scene) << r.error;
    return r.scene ? std::move(*r.scene) : Scene{};
}

Settings pointLightOver(const char* update) {
    Settings s = topDownShadowView(loadShippedPreset("default"));
    for (const char* kv : {"lights.0.type=point", "lights.0.position=1,6,-1", "lights.0.range=40",
                           "lights.0.shadow.resolution=512", "animation.play=Spin"})
        EXPECT_EQ(applySettingOverride(s, kv), "") << kv;
    EXPECT_EQ(applySettingOverride(s, std::string("lights.0.shadow.update=") + update), "");
    return s;
}

// Poses `scene` in place at `time` (as the flicker measure does) and renders it.
View renderAt(Renderer& renderer, Scene& scene, Settings s, float time) {
    s.animation.time = time;
    EXPECT_EQ(poseScene(scene, s.animation), "");
    View v = renderView(renderer, scene, s, 160, 160);
    EXPECT_TRUE(v.stats.ok) << v.stats.error;
    return v;
}

// The Spinner's bounding sphere as the renderer placed it last.
CasterSphere spinnerSphere(const Renderer& renderer, const Scene& scene) {
    for (const GpuDraw& d : renderer.gpuScene()->draws()) {
        const int node = scene.instances[d.instance].node;
        if (node >= 0 && scene.nodes[std::size_t(node)].name == "Spinner") return casterSphere(d);
    }
    ADD_FAILURE() << "no Spinner draw";
    return {};
}

int viewsThatRan(const FrameStats& stats) {
    return int(std::count_if(stats.views.begin(), stats.views.end(), [](const ShadowViewStats& v) { return v.ran; }));
}

long differingTexels(const ShadowMap& a, const ShadowMap& b) {
    const std::vector<float> da = a.readDepth(), db = b.readDepth();
    EXPECT_EQ(da.size(), db.size());
    long n = 0;
    for (std::size_t i = 0; i < std::min(da.size(), db.size()); ++i) n += da[i] != db[i];
    return n;
}

long differingPixels(const View& a, const View& b) {
    long n = 0;
    for (std::size_t i = 0; i + 3 < std::min(a.rgba.size(), b.rgba.size()); i += 4) n += a.rgba[i] != b.rgba[i];
    return n;
}

TEST_F(CachedShadows, OneMovingCasterRerendersOnlyTheFacesItTouchesAndAStillFrameNone) {
    for (const char* update : {"onChange", "cachedStatic"}) {
        SCOPED_TRACE(update);
        Scene scene = spinningBoxes();
        const Settings s = pointLightOver(update);
        Renderer renderer;
        const View first = renderAt(renderer, scene, s, 0.2f);
        EXPECT_EQ(viewsThatRan(first.stats), 6);
        const CasterSphere before = spinnerSphere(renderer, scene);
        const View moved = renderAt(renderer, scene, s, 0.45f);
        const CasterSphere after = spinnerSphere(renderer, scene);
        ASSERT_FALSE(before == after);
        int touched = 0;
        for (const ShadowViewStats& v : moved.stats.views) {
            const bool holds = casterInVolume(before, v.space) || casterInVolume(after, v.space);
            touched += holds;
            EXPECT_EQ(v.ran, holds) << v.name << ": " << v.cache << ": " << v.reason;
            EXPECT_EQ(v.cache, !holds ? "reused" : std::string(update) == "cachedStatic" ? "static + dynamic" : "full")
                << v.name;
            if (holds) EXPECT_EQ(v.reason, "Spinner moved") << v.name;
            // Into a cached face only the Spinner is drawn, within the texels it covers.
            if (holds && std::string(update) == "cachedStatic") {
                EXPECT_EQ(v.castersDrawn, 1) << v.name;
                EXPECT_GT(v.texelsRedrawn, 0u) << v.name;
                EXPECT_LT(v.texelsRedrawn, std::size_t(512 * 512)) << v.name;
            }
        }
        EXPECT_GT(touched, 0);
        EXPECT_LT(touched, 6);
        // Nothing moved: no face renders.
        const View still = renderAt(renderer, scene, s, 0.45f);
        EXPECT_EQ(viewsThatRan(still.stats), 0) << still.stats.shadowPass.reason;
    }
}

TEST_F(CachedShadows, TheCachedFramesMapsEqualAFullRerendersTexelForTexel) {
    Scene cachedScene = spinningBoxes(), fullScene = spinningBoxes();
    Renderer cached, full;
    const Settings s = pointLightOver("cachedStatic");
    int staticPlusDynamic = 0;  // views drawn from their cached static depth along the way
    for (float t : {0.1f, 0.35f, 0.6f, 0.85f})
        for (const ShadowViewStats& v : renderAt(cached, cachedScene, s, t).stats.views)
            staticPlusDynamic += v.cache == "static + dynamic";
    EXPECT_GE(staticPlusDynamic, 3);
    Settings everyFrame = s;
    everyFrame.lights[0].shadow.update = ShadowUpdate::EveryFrame;
    renderAt(full, fullScene, everyFrame, 0.6f);
    const View fullView = renderAt(full, fullScene, everyFrame, 0.85f);
    const View cachedView = renderAt(cached, cachedScene, s, 0.85f);  // still: its maps are the last motion's
    EXPECT_EQ(viewsThatRan(fullView.stats), 6);
    int reused = 0;
    for (int face = 0; face < 6; ++face) {
        const ShadowMap* a = cached.viewMap(0, face);
        const ShadowMap* b = full.viewMap(0, face);
        ASSERT_TRUE(a && b);
        EXPECT_EQ(differingTexels(*a, *b), 0) << "face " << face;
    }
    for (const ShadowViewStats& v : cachedView.stats.views) reused += v.cache == "reused";
    EXPECT_EQ(reused, 6);
    saveView(cachedView, "cached-static-spinner");
    EXPECT_EQ(differingPixels(cachedView, fullView), 0);
}

}  // namespace
}  // namespace shadowlab::test
