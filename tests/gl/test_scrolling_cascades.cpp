// The scrolling cascade cache (issue 22, "With stable cascades the camera moves the cascades"): on builtin:city a
// camera walks down the street with a cachedStatic sun in four stable cascades. A cascade whose snapped origin moved
// by whole texels scrolls its cached static depth and draws only the strips that came into view; its maps equal, texel
// for texel, those a fresh renderer draws whole at the same camera (its pages: views/cascade_scroll.h), and differ
// from a plain draw through the cascade's matrix (everyFrame) only in the last bits of a float's depth.
#include "gl_fixture.h"

#include "light/scene_lights.h"
#include "scene/builtin_scenes.h"
#include "shadow/shadow_pass.h"

#include <cmath>
#include <cstdio>

namespace shadowlab::test {
namespace {

class ScrollingCascades : public GlTest {};

constexpr int kResolution = 512;

Settings streetWalk(const Scene& scene, ShadowUpdate update) {
    Settings s = withEffectiveLights(loadShippedPreset("default"), scene);
    s.useSceneLights = false;
    LightSettings& sun = s.lights[0];
    sun.projection.fit = ProjectionFit::Cascades;
    sun.projection.cascadeCount = 4;
    sun.projection.cascadeFit = CascadeFit::Stable;
    sun.projection.depthBounds = DepthBounds::Off;
    sun.shadow.resolution = kResolution;
    sun.shadow.update = update;
    s.camera.autoFrame = false;
    return s;
}

struct Difference {
    long texels = 0;
    long beyondRounding = 0;  // by more than a float's last bits at depth 1
    double largest = 0.0;
};

Difference difference(const ShadowMap& a, const ShadowMap& b) {
    const std::vector<float> da = a.readDepth(), db = b.readDepth();
    EXPECT_EQ(da.size(), db.size());
    Difference d;
    for (std::size_t i = 0; i < std::min(da.size(), db.size()); ++i) {
        d.texels += da[i] != db[i];
        d.beyondRounding += std::abs(da[i] - db[i]) > 1e-6f;
        d.largest = std::max(d.largest, double(std::abs(da[i] - db[i])));
    }
    return d;
}

const ShadowMap& cascadeMap(const Renderer& renderer, int cascade) {
    const ShadowMap* map = renderer.viewMap(ShadowViewId{0, ShadowViewKind::Cascade, cascade});
    EXPECT_TRUE(map);
    return *map;
}

TEST_F(ScrollingCascades, AWalkDownTheStreetScrollsTheCascadesAndEqualsAFullRerender) {
    const Scene scene = loadBuiltin("city");
    Renderer scrolling, plain;
    Settings cached = streetWalk(scene, ShadowUpdate::CachedStatic);
    Settings everyFrame = streetWalk(scene, ShadowUpdate::EveryFrame);
    long long redrawn = 0, texels = 0;
    int scrolled = 0;
    Difference fromPlain;
    for (int frame = 0; frame < 8; ++frame) {
        // 0.4 m a frame down the street (toward -z): a texel or so of the near cascades, less of the far ones.
        const glm::dvec3 step(0.0, 0.0, -0.4 * frame);
        for (Settings* s : {&cached, &everyFrame}) {
            s->camera.position = glm::dvec3(builtin::kCityEye) + step;
            s->camera.target = glm::dvec3(builtin::kCityEyeTarget) + step;
        }
        const View walked = renderView(scrolling, scene, cached, 160, 90);
        Renderer fresh;  // draws every cascade whole at this camera
        renderView(fresh, scene, cached, 160, 90);
        renderView(plain, scene, everyFrame, 160, 90);
        ASSERT_EQ(walked.stats.views.size(), 4u);
        for (int v = 0; v < 4; ++v) {
            const ShadowViewStats& view = walked.stats.views[std::size_t(v)];
            SCOPED_TRACE("frame " + std::to_string(frame) + ", " + view.name + ": " + view.cache + ": " + view.reason);
            EXPECT_EQ(difference(cascadeMap(scrolling, v), cascadeMap(fresh, v)).texels, 0);
            const Difference d = difference(cascadeMap(scrolling, v), cascadeMap(plain, v));
            fromPlain.texels += d.texels;
            fromPlain.beyondRounding += d.beyondRounding;
            // Pages round as a plain draw does, elsewhere: only a triangle edge through a texel centre may flip.
            EXPECT_LE(d.beyondRounding, kResolution * kResolution / 10000) << "texels off a plain draw's by > 1e-6";
            fromPlain.largest = std::max(fromPlain.largest, d.largest);
            if (view.cache != "scrolled") continue;
            EXPECT_EQ(view.reason.rfind("scrolled ", 0), 0u);
            ++scrolled;
            redrawn += (long long)view.texelsRedrawn;
            texels += (long long)kResolution * kResolution;
        }
    }
    ASSERT_GE(scrolled, 4) << "the near cascades move by whole texels along the walk";
    const double share = double(redrawn) / double(texels);
    std::printf("[ scrolling ] %d cascade draws scrolled, %.2f %% of their texels re-rendered; against a plain draw "
                "(everyFrame): %ld texels differ, %ld by more than 1e-6 (at most %.3g)\n",
                scrolled, 100.0 * share, fromPlain.texels, fromPlain.beyondRounding, fromPlain.largest);
    EXPECT_GT(redrawn, 0) << "the camera moved: some strip came into view";
    EXPECT_LT(share, 0.10);
}

}  // namespace
}  // namespace shadowlab::test
