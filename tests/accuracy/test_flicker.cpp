// Flicker (flicker.h, motion.h): the pair comparison on synthetic buffers, the motions' geometry, the option
// errors, and the measure on builtin:textbook — a camera moved by sub-texel steps flickers exactly 0 with no shadow
// view re-rendered; a light turned by a sub-texel angle flickers at the shadow edges on an unsnapped point-filtered
// map; a larger turn moves the true shadow (V changes) far more than it flickers.
#include "accuracy/flicker.h"
#include "gl_fixture.h"
#include "reference_fixture.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace shadowlab::test {
namespace {

constexpr int kWidth = 480;
constexpr int kHeight = 270;

TEST(FlickerPair, CountsFlipsOnlyWhereVisibilityStays) {
    // Pixels: 0 lit->lit S 0.9->0.2 (flicker), 1 lit->lit S 0.9->0.7 (|dS| 0.2, no flip), 2 lit->shadowed S
    // 0.9->0.1 (V changed, not flicker), 3 shadowed->shadowed S 0->0, 4 not measured in the second half (S flips).
    const std::vector<PixelClass> before{PixelClass::Lit, PixelClass::Lit, PixelClass::Lit, PixelClass::Shadowed,
                                         PixelClass::Lit};
    const std::vector<PixelClass> after{PixelClass::Lit, PixelClass::Lit, PixelClass::Shadowed, PixelClass::Shadowed,
                                        PixelClass::Lit};
    const std::vector<float> sBefore{0.9f, 0.9f, 0.9f, 0.0f, 1.0f}, sAfter{0.2f, 0.7f, 0.1f, 0.0f, 0.0f};
    const std::vector<std::uint8_t> all{1, 1, 1, 1, 1}, notLast{1, 1, 1, 1, 0};
    std::vector<std::uint8_t> mask;
    const FlickerCounts c = compareFlickerPair({&before, &sBefore, &all}, {&after, &sAfter, &notLast}, &mask);
    EXPECT_EQ(c.measured, 4u);
    EXPECT_EQ(c.flicker, 1u);
    EXPECT_EQ(c.vChanged, 1u);
    EXPECT_EQ(c.visibleDelta, 2u);
    EXPECT_DOUBLE_EQ(c.flickerPercent, 25.0);
    EXPECT_DOUBLE_EQ(c.vChangedPercent, 25.0);
    EXPECT_NEAR(c.meanAbsDeltaS, (0.7 + 0.2 + 0.0) / 3.0, 1e-6);
    EXPECT_EQ(mask, (std::vector<std::uint8_t>{1, 0, 0, 0, 0}));
}

TEST(FlickerMotion, CameraSlidesAlongItsRightVectorByFrameTimesStep) {
    Camera start;
    start.position = {0.0, 0.0, 10.0};
    start.target = {0.0, 0.0, 0.0};
    Motion motion;
    motion.kind = MotionKind::Camera;
    motion.step = 0.01;
    motion.frames = 200;
    const Camera c = cameraAtFrame(start, motion, 150);
    // Looking down -z, right is +x.
    EXPECT_NEAR(c.position.x, 1.5, 1e-12);
    EXPECT_NEAR(c.target.x, 1.5, 1e-12);
    EXPECT_DOUBLE_EQ(c.position.z, 10.0);
    motion.direction = glm::dvec3(0.0, 2.0, 0.0);
    EXPECT_NEAR(cameraAtFrame(start, motion, 3).position.y, 0.03, 1e-12);
    // At 1e6 the step survives (double precision).
    start.position.x += 1e6;
    start.target.x += 1e6;
    motion.direction.reset();
    motion.step = 0.001;
    EXPECT_NEAR(cameraAtFrame(start, motion, 1).position.x - start.position.x, 0.001, 1e-9);
}

TEST(FlickerMotion, CameraTurnsItsViewAboutItsPosition) {
    Camera start;
    start.position = {0.0, 2.0, 10.0};
    start.target = {0.0, 2.0, 0.0};
    Motion motion;
    motion.kind = MotionKind::CameraTurn;
    motion.step = 0.5;
    motion.frames = 200;
    const Camera c = cameraAtFrame(start, motion, 180);  // 90 degrees about world up
    EXPECT_EQ(c.position, start.position);
    EXPECT_NEAR(glm::length(c.target - c.position), 10.0, 1e-9);
    EXPECT_NEAR(std::abs(c.target.x), 10.0, 1e-9);
    EXPECT_NEAR(c.target.y, 2.0, 1e-12);
    EXPECT_EQ(parseMotion("camera-turn"), MotionKind::CameraTurn);
    EXPECT_EQ(motionNames(), "camera, camera-turn, light or animation");
}

TEST(FlickerMotion, LightTurnsByFrameTimesStepAboutTheDefaultAxis) {
    Bounds bounds;
    bounds.extend({-1.0f, -1.0f, -1.0f});
    bounds.extend({1.0f, 1.0f, 1.0f});
    LightSettings sun;
    sun.direction = {-0.4f, -1.0f, -0.3f};
    Motion motion;
    motion.kind = MotionKind::Light;
    motion.step = 0.25;
    motion.frames = 10;
    const glm::dvec3 d0 = glm::normalize(glm::dvec3(sun.direction));
    const glm::dvec3 d4 = glm::normalize(glm::dvec3(lightAtFrame(sun, motion, bounds, 4).direction));
    EXPECT_NEAR(glm::degrees(std::acos(std::clamp(glm::dot(d0, d4), -1.0, 1.0))), 1.0, 1e-3);
    // The default axis is perpendicular to the direction and to world up.
    const glm::dvec3 axis = lightRotationAxis(sun, motion, bounds);
    EXPECT_NEAR(glm::dot(axis, d0), 0.0, 1e-12);
    EXPECT_NEAR(axis.y, 0.0, 1e-12);
    // Straight down: world X.
    sun.direction = {0.0f, -1.0f, 0.0f};
    EXPECT_EQ(lightRotationAxis(sun, motion, bounds), glm::dvec3(1.0, 0.0, 0.0));
    // A point light turns its position about the scene's centre, at the same distance.
    LightSettings bulb;
    bulb.type = LightType::Point;
    bulb.position = {3.0f, 4.0f, 0.0f};
    const LightSettings turned = lightAtFrame(bulb, motion, bounds, 8);
    EXPECT_NEAR(glm::length(glm::dvec3(turned.position)), 5.0, 1e-5);
    EXPECT_GT(glm::length(glm::dvec3(turned.position - bulb.position)), 0.01);
    // A camera motion leaves the light alone, a light motion the camera.
    motion.kind = MotionKind::Camera;
    EXPECT_EQ(lightAtFrame(bulb, motion, bounds, 8), bulb);
}

TEST(FlickerMotion, OptionErrorsNameTheOption) {
    Bounds bounds;
    bounds.extend({-5.0f, 0.0f, -5.0f});
    bounds.extend({5.0f, 2.0f, 5.0f});
    Motion m;
    m.step = 0.01;
    m.frames = 1;
    EXPECT_NE(motionError(m, bounds).find("--frames 1"), std::string::npos) << motionError(m, bounds);
    m.frames = kMaxMotionFrames + 1;
    EXPECT_NE(motionError(m, bounds).find("--frames"), std::string::npos);
    m.frames = 3;
    EXPECT_EQ(motionError(m, bounds), "");
    m.step = std::nan("");
    EXPECT_NE(motionError(m, bounds).find("--step"), std::string::npos);
    m.step = 1000.0;  // camera: far beyond the scene's diameter
    EXPECT_NE(motionError(m, bounds).find("diameter"), std::string::npos) << motionError(m, bounds);
    m.kind = MotionKind::Light;
    m.step = 90.0;
    EXPECT_NE(motionError(m, bounds).find("degrees"), std::string::npos) << motionError(m, bounds);
    m.step = 0.1;
    m.direction = glm::dvec3(0.0);
    EXPECT_NE(motionError(m, bounds).find("--direction"), std::string::npos);
    EXPECT_EQ(parseMotion("light"), MotionKind::Light);
    EXPECT_FALSE(parseMotion("sideways"));
}

class FlickerTest : public GlTest {};

// The auto-framed view of the whole scene: a texel of a 256² map spans about 2 pixels at this size.
Settings textbookSettings(FilterKind filter, int resolution) {
    Settings s = loadShippedPreset("default");
    s.filter.kind = filter;
    s.lights[0].shadow.resolution = resolution;
    return s;
}

// The textbook, its view and a meter; play() measures a motion of light 0 in that view.
struct Textbook {
    Textbook(FilterKind filter, int resolution)
        : scene(loadBuiltin("textbook")),
          settings(textbookSettings(filter, resolution)),
          camera(cameraFor(settings.camera, scene, double(kWidth) / kHeight)) {}
    FlickerReport play(MotionKind kind, double step, int frames) {
        Motion motion;
        motion.kind = kind;
        motion.step = step;
        motion.frames = frames;
        return measureFlicker(meter, scene, settings, camera, kWidth, kHeight, motion);
    }
    Scene scene;
    Settings settings;
    Camera camera;
    AccuracyMeter meter;
};

void savePicture(const std::vector<std::uint8_t>& rgba, int w, int h, const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(SHADOWLAB_TEST_OUTPUT) / "accuracy";
    std::filesystem::create_directories(dir);
    EXPECT_EQ(writePng((dir / (name + ".png")).string(), w, h, 4, rgba.data(), false), "");
}

std::size_t maskCount(const std::vector<std::uint8_t>& mask) {
    std::size_t n = 0;
    for (std::uint8_t m : mask) n += m;
    return n;
}

TEST_F(FlickerTest, CameraMotionFlickersExactlyZeroAndRerendersNoShadowView) {
    Textbook t(FilterKind::Point, 512);
    const AccuracyReport first = t.meter.measure(t.scene, t.settings, t.camera, kWidth, kHeight);
    ASSERT_TRUE(first.ok) << first.error;
    // 0.2 texel of the map per frame.
    const FlickerReport r = t.play(MotionKind::Camera, 0.2 * first.texelWorldSize, 4);
    ASSERT_TRUE(r.ok) << r.error;
    savePicture(r.overlayRgba, r.width, r.height, "flicker-textbook-camera");
    ASSERT_EQ(r.pairs.size(), 3u);
    EXPECT_NEAR(r.stepTexels, 0.2, 1e-9);
    for (const FlickerPair& pair : r.pairs) {
        EXPECT_EQ(pair.counts.flicker, 0u);
        EXPECT_EQ(pair.counts.vChanged, 0u) << "the light did not move";
        EXPECT_EQ(pair.shadowViewsRendered, 0u) << "a scene-fitted map must not follow the camera";
        EXPECT_GT(pair.counts.measured, 10000u);
    }
    EXPECT_EQ(r.maxFlickerPercent, 0.0);
    EXPECT_EQ(maskCount(r.flickerMask), 0u);
    // The camera did move: the frames see different pixels.
    EXPECT_NE(r.frames.front().numbers.counts.lit, r.frames.back().numbers.counts.lit);

    // Turning the camera (HARD_CASES.md case 7's second half) keeps the maps too.
    const FlickerReport turned = t.play(MotionKind::CameraTurn, 0.1, 3);
    ASSERT_TRUE(turned.ok) << turned.error;
    EXPECT_EQ(turned.maxFlickerPercent, 0.0);
    for (const FlickerPair& pair : turned.pairs) EXPECT_EQ(pair.shadowViewsRendered, 0u);
    EXPECT_NE(turned.frames.front().numbers.counts.lit, turned.frames.back().numbers.counts.lit);
}

TEST_F(FlickerTest, SubTexelLightTurnFlickersAtShadowEdgesOfAnUnsnappedMap) {
    Textbook t(FilterKind::Point, 256);
    // 0.2 degrees: about a quarter texel of the 256² map (checked below).
    const FlickerReport r = t.play(MotionKind::Light, 0.2, 4);
    ASSERT_TRUE(r.ok) << r.error;
    savePicture(r.overlayRgba, r.width, r.height, "flicker-textbook-light");
    savePicture(r.worstPreviousRgba, r.width, r.height, "flicker-textbook-light-worst-a");
    savePicture(r.worstCurrentRgba, r.width, r.height, "flicker-textbook-light-worst-b");
    EXPECT_GT(r.stepTexels, 0.1);
    EXPECT_LT(r.stepTexels, 1.0) << "the step must be sub-texel";
    EXPECT_GT(r.maxFlickerPercent, 0.0);
    EXPECT_GT(maskCount(r.flickerMask), 0u);
    EXPECT_LT(r.maxFlickerPercent, 5.0) << "only pixels at the edges can flip";
    for (const FlickerPair& pair : r.pairs) EXPECT_GE(pair.shadowViewsRendered, 1u) << "the light moved";

    // Every flickering pixel lies near a true shadow edge of the last frame: within a few pixels some neighbour has
    // the other visibility (a texel of the 256² map spans about 2 pixels here; 6 leaves room for the staircase).
    Settings last = t.settings;
    last.lights[0] = lightAtFrame(t.settings.lights[0], r.motion, t.scene.bounds, r.motion.frames - 1);
    const AccuracyReport lastFrame = t.meter.measure(t.scene, last, t.camera, kWidth, kHeight);
    ASSERT_TRUE(lastFrame.ok);
    constexpr int kReach = 6;
    std::size_t far = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = std::size_t(y) * kWidth + std::size_t(x);
            if (!r.flickerMask[i]) continue;
            bool nearEdge = false;
            for (int dy = -kReach; dy <= kReach && !nearEdge; ++dy)
                for (int dx = -kReach; dx <= kReach && !nearEdge; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= kWidth || ny >= kHeight) continue;
                    const std::size_t j = std::size_t(ny) * kWidth + std::size_t(nx);
                    nearEdge = isScored(lastFrame.pixelClass[j]) &&
                               isLit(lastFrame.pixelClass[j]) != isLit(lastFrame.pixelClass[i]);
                }
            far += nearEdge ? 0 : 1;
        }
    EXPECT_EQ(far, 0u) << "of " << maskCount(r.flickerMask) << " flickering pixels";
}

TEST_F(FlickerTest, LargerLightTurnMovesTheTrueShadowMoreThanItFlickers) {
    Textbook t(FilterKind::Pcf, 2048);
    const FlickerReport r = t.play(MotionKind::Light, 2.0, 2);
    ASSERT_TRUE(r.ok) << r.error;
    savePicture(r.overlayRgba, r.width, r.height, "flicker-textbook-light-2deg");
    EXPECT_GT(r.stepTexels, 10.0);
    // A 2 degree turn moves the floating box's detached shadow (2.75 above the floor) by 2.75 x 0.035 = 0.1 world
    // units, about 1.5 pixels of this view: a band along its ~120 pixels of outline, some 0.25 % of the ~70000
    // measured pixels (the cube's and sphere's contact shadows move less).
    EXPECT_GT(r.maxVChangedPercent, 0.1);
    EXPECT_LT(r.maxVChangedPercent, 1.0);
    EXPECT_LT(r.maxFlickerPercent, r.maxVChangedPercent);
}

TEST_F(FlickerTest, BadMotionOrLightIsRefusedWithTheReason) {
    Textbook t(FilterKind::Pcf, 512);
    Motion motion;
    motion.frames = 1;
    FlickerReport r = measureFlicker(t.meter, t.scene, t.settings, t.camera, kWidth, kHeight, motion);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("--frames"), std::string::npos) << r.error;
    motion.frames = 2;
    motion.light = 5;
    r = measureFlicker(t.meter, t.scene, t.settings, t.camera, kWidth, kHeight, motion);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("lights.5"), std::string::npos) << r.error;
    // A point light turns about the scene's centre: sitting there, it would not move at all.
    motion.light = 0;
    motion.kind = MotionKind::Light;
    t.settings.lights[0].type = LightType::Point;
    t.settings.lights[0].position = t.scene.bounds.center();
    r = measureFlicker(t.meter, t.scene, t.settings, t.camera, kWidth, kHeight, motion);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("scene's centre"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace shadowlab::test
