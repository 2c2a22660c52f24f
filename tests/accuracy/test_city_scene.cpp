// builtin:city (issue 20): the default preset measures it at eye height, and it shows the opening figures: a
// 2048^2 map fitted to the 2 km city has texels of about 1.4 world units, and the lamp posts near the eye, 0.16 m
// thick, lose their shadows (the exact reference shadows those ground pixels, the tool's frame leaves them lit).
#include "gl_fixture.h"
#include "reference_fixture.h"
#include "scene/builtin_scenes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace shadowlab::test {
namespace {

class CityScene : public GlTest {};

constexpr int kWidth = 640;
constexpr int kHeight = 360;

// The pixel (row 0 = top) where the camera sees world point p, or {-1, -1} off screen.
glm::ivec2 pixelOf(const Camera& camera, const glm::dvec3& p) {
    const glm::dmat4 viewProjection = camera.projection(double(kWidth) / kHeight) * camera.view(glm::dvec3(0.0));
    const glm::dvec4 clip = viewProjection * glm::dvec4(p, 1.0);
    if (clip.w <= 0.0) return {-1, -1};
    const double x = (clip.x / clip.w * 0.5 + 0.5) * kWidth, y = (0.5 - clip.y / clip.w * 0.5) * kHeight;
    if (x < 0.0 || y < 0.0 || x >= kWidth || y >= kHeight) return {-1, -1};
    return {int(x), int(y)};
}

// True when the ray from p toward the light (along -d) crosses the axis-aligned box [lo, hi] (slab test).
bool rayHitsBox(const glm::dvec3& p, const glm::dvec3& d, const glm::dvec3& lo, const glm::dvec3& hi) {
    double tMin = 1e-6, tMax = 1e30;
    for (int a = 0; a < 3; ++a) {
        const double dir = -d[a];
        if (std::abs(dir) < 1e-12) {
            if (p[a] < lo[a] || p[a] > hi[a]) return false;
            continue;
        }
        double t0 = (lo[a] - p[a]) / dir, t1 = (hi[a] - p[a]) / dir;
        if (t0 > t1) std::swap(t0, t1);
        tMin = std::max(tMin, t0);
        tMax = std::min(tMax, t1);
        if (tMin > tMax) return false;
    }
    return true;
}

// Every mesh of the city is one axis-aligned box (or the ground quad): p is shadowed by a lamp post and no building.
bool shadowedOnlyByALampPost(const Scene& scene, const glm::dvec3& p, const glm::dvec3& d) {
    bool byPost = false;
    for (const Mesh& m : scene.meshes) {
        if (m.name == "floor") continue;
        glm::dvec3 lo(1e30), hi(-1e30);
        for (const glm::vec3& v : m.positions) {
            lo = glm::min(lo, glm::dvec3(v));
            hi = glm::max(hi, glm::dvec3(v));
        }
        if (!rayHitsBox(p, d, lo, hi)) continue;
        if (m.name == "building" || m.name == "tower" || m.name == "tower-top" || m.name == "sidewalk") return false;
        byPost = byPost || m.name == "lamp-post";  // its own arm and head may be in the way too
    }
    return byPost;
}

TEST_F(CityScene, AFittedMapsTexelIsWiderThanTheLampPostsNearTheEyeAndTheirShadowsAreLost) {
    const Scene scene = loadBuiltin("city");
    // The default preset under the city's own sun (useSceneLights): low, shining down the street, so the posts'
    // shadows fall on lit pavement (the default light leaves this stretch of street in the buildings' shadow).
    Settings settings = loadShippedPreset("default");
    settings.useSceneLights = true;
    ASSERT_TRUE(settings.lights[0].projection.autoFit);
    ASSERT_EQ(settings.lights[0].shadow.resolution, 2048);
    const Camera camera = cameraFor(settings.camera, scene, double(kWidth) / kHeight);
    // The auto-framed camera stands at the scene's viewpoint; an explicit camera is kept.
    ASSERT_EQ(camera.position, scene.viewpoint->position);
    EXPECT_EQ(camera.target, scene.viewpoint->target);
    EXPECT_LT(camera.nearPlane, 0.5) << "the furniture a few metres away is not clipped";
    CameraSettings placed = settings.camera;
    placed.autoFrame = false;
    EXPECT_EQ(cameraFor(placed, scene, 16.0 / 9.0).position, placed.position);
    AccuracyMeter meter;
    const AccuracyReport r = meter.measure(scene, settings, camera, kWidth, kHeight);
    ASSERT_TRUE(r.ok) << r.error;
    saveOverlay(r, "city-default");
    std::printf("city, default preset under its sun, %dx%d: texel %.3f world units, acne %.3f %%, leak %.3f %%, "
                "wrong %.3f %%, edge error %.1f texels = %.1f screen pixels\n",
                kWidth, kHeight, r.texelWorldSize, r.acnePercent, r.leakPercent, r.wrongPercent,
                r.edgeErrorP95Texels, r.edgeErrorP95ScreenPixels);
    EXPECT_NEAR(r.texelWorldSize, 1.4, 0.1);
    EXPECT_GT(r.counts.measured, std::size_t(kWidth * kHeight / 2)) << "the street fills the view";

    // The shadow of each lamp post ahead of the eye within 40 m, from 1.5 m up the pole to 5.5 m (clear of the
    // contact and the arm), on the sidewalk (y = curb) or the road (y = 0) where it falls.
    const glm::dvec3 d = glm::normalize(glm::dvec3(scene.lights[0].direction));
    const glm::dvec3 eye = scene.viewpoint->position;
    const double curb = 0.5 * builtin::kCityStreetWidth;
    int samples = 0, trulyShadowed = 0, lost = 0;
    for (const Mesh& m : scene.meshes) {
        if (m.name != "lamp-post") continue;
        glm::dvec3 base(0.0);
        for (const glm::vec3& p : m.positions) base += glm::dvec3(p);
        base /= double(m.positions.size());
        base.y = builtin::kCityCurbHeight;
        if (base.z > eye.z || glm::length(base - eye) > 40.0) continue;
        for (double h = 1.5; h <= 5.5; h += 0.25) {
            const glm::dvec3 onPole = base + glm::dvec3(0.0, h, 0.0);
            glm::dvec3 ground = onPole + d * ((onPole.y - builtin::kCityCurbHeight) / -d.y);
            if (std::abs(ground.x) < curb) ground = onPole + d * (onPole.y / -d.y);  // on the road
            const glm::ivec2 px = pixelOf(camera, ground);
            if (px.x < 0 || !shadowedOnlyByALampPost(scene, ground, d)) continue;  // not in a building's shadow
            const std::size_t i = std::size_t(px.y) * kWidth + std::size_t(px.x);
            ++samples;
            if (r.pixelClass[i] != PixelClass::Shadowed) continue;
            ++trulyShadowed;
            lost += r.pixelShadow[i] > 0.5f;
        }
    }
    std::printf("lamp-post shadows near the eye (nothing else in the way): %d samples, %d truly shadowed, %d of them "
                "lit in the tool's frame\n",
                samples, trulyShadowed, lost);
    ASSERT_GE(samples, 10);
    EXPECT_GE(trulyShadowed, samples * 3 / 4) << "the reference holds the posts' shadows where they fall";
    EXPECT_GE(lost, trulyShadowed * 3 / 4) << "a 1.4 m texel cannot hold a 0.16 m post's shadow";
}

}  // namespace
}  // namespace shadowlab::test
