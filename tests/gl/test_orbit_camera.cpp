// The editor's orbit camera (pure maths, no GL context needed): orbiting keeps the distance and the target, pitch
// stops short of the poles, a pan keeps the point under the cursor under the cursor, zoom is multiplicative and
// clamped, F fills the view with the scene as auto-framing does, and Camera round trips.
#include "frame/orbit_camera.h"

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace shadowlab;

namespace {

Bounds cube(double half, glm::vec3 center = glm::vec3(0.0f)) {
    Bounds b;
    b.extend(center - glm::vec3(float(half)));
    b.extend(center + glm::vec3(float(half)));
    return b;
}

// Pixel position (x right, y down) of a world point in a width x height view of `camera`.
glm::dvec2 toPixel(const Camera& camera, const glm::dvec3& world, int width, int height) {
    const glm::dvec4 clip = camera.projection(double(width) / height) * camera.view(glm::dvec3(0.0)) *
                            glm::dvec4(world, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {(ndc.x * 0.5 + 0.5) * width, (0.5 - ndc.y * 0.5) * height};
}

Camera startCamera() {
    Camera c;
    c.position = {8.0, 6.0, 10.0};
    c.target = {1.0, 0.0, -1.0};
    c.fovYDeg = 45.0;
    return c;
}

}  // namespace

TEST(OrbitCamera, RoundTripsTheCameraItStartsFrom) {
    const Camera start = startCamera();
    OrbitCamera orbit(start, cube(2.0));
    const Camera back = orbit.toCamera();
    EXPECT_NEAR(glm::distance(back.position, start.position), 0.0, 1e-9);
    EXPECT_NEAR(glm::distance(back.target, start.target), 0.0, 1e-12);
    EXPECT_EQ(back.fovYDeg, start.fovYDeg);
    EXPECT_GT(back.nearPlane, 0.0);
    EXPECT_GT(back.farPlane, glm::distance(back.position, back.target) + 2.0);  // the whole scene fits
}

TEST(OrbitCamera, OrbitKeepsTargetAndDistanceAndTurnsTheSceneWithTheMouse) {
    OrbitCamera orbit(startCamera(), cube(2.0));
    const double distance = orbit.distance();
    const glm::dvec3 target = orbit.target();
    // Dragging right turns the scene right: a point in front of the target (toward the eye) moves right on screen.
    const Camera before = orbit.toCamera();
    const glm::dvec3 front = target + glm::normalize(before.position - target) * 1.0;
    const double xBefore = toPixel(before, front, 800, 600).x;
    orbit.orbit(40.0, 0.0);
    const Camera after = orbit.toCamera();
    EXPECT_GT(toPixel(after, front, 800, 600).x, xBefore + 10.0);
    EXPECT_NEAR(glm::distance(after.position, target), distance, 1e-9);
    EXPECT_NEAR(glm::distance(after.target, target), 0.0, 1e-12);

    // Dragging down raises the eye (more from above).
    const double heightBefore = orbit.eye().y;
    orbit.orbit(0.0, 30.0);
    EXPECT_GT(orbit.eye().y, heightBefore);
}

TEST(OrbitCamera, PitchStopsShortOfThePolesSoTheViewStaysFinite) {
    OrbitCamera orbit(startCamera(), cube(2.0));
    orbit.orbit(0.0, 1e6);
    EXPECT_NEAR(orbit.pitchRad(), glm::radians(OrbitCamera::kMaxPitchDeg), 1e-12);
    const glm::dmat4 view = orbit.toCamera().view(glm::dvec3(0.0));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(view[c][r]));
    orbit.orbit(0.0, -1e6);
    EXPECT_NEAR(orbit.pitchRad(), -glm::radians(OrbitCamera::kMaxPitchDeg), 1e-12);
    // Straight-down start camera: pitch is clamped on the way in too.
    Camera down;
    down.position = {0.0, 10.0, 0.0};
    down.target = {0.0, 0.0, 0.0};
    OrbitCamera fromAbove(down, cube(2.0));
    EXPECT_LE(fromAbove.pitchRad(), glm::radians(OrbitCamera::kMaxPitchDeg) + 1e-12);
}

TEST(OrbitCamera, PanKeepsThePointUnderTheCursorUnderTheCursor) {
    const int width = 800, height = 600;
    OrbitCamera orbit(startCamera(), cube(2.0));
    const glm::dvec3 point = orbit.target();  // a point at the target's depth
    const glm::dvec2 before = toPixel(orbit.toCamera(), point, width, height);
    orbit.pan(37.0, -21.0, height);
    const glm::dvec2 after = toPixel(orbit.toCamera(), point, width, height);
    EXPECT_NEAR(after.x - before.x, 37.0, 0.05);
    EXPECT_NEAR(after.y - before.y, -21.0, 0.05);
}

TEST(OrbitCamera, ZoomIsMultiplicativeAndClamped) {
    OrbitCamera orbit(startCamera(), cube(2.0));
    const double d0 = orbit.distance();
    orbit.zoom(1.0);
    EXPECT_NEAR(orbit.distance(), d0 * OrbitCamera::kZoomPerWheelStep, 1e-9);
    orbit.zoom(-2.0);
    EXPECT_NEAR(orbit.distance(), d0 / OrbitCamera::kZoomPerWheelStep, 1e-9);
    const double radius = double(cube(2.0).radius());
    orbit.zoom(1000.0);
    EXPECT_NEAR(orbit.distance(), OrbitCamera::kMinDistanceRadii * radius, 1e-9);
    orbit.zoom(-10000.0);
    EXPECT_NEAR(orbit.distance(), OrbitCamera::kMaxDistanceRadii * radius, 1e-6);
    EXPECT_GT(orbit.toCamera().farPlane, orbit.distance());  // near/far follow the eye
}

TEST(OrbitCamera, FrameFillsTheViewWithTheSceneFromTheSameDirection) {
    // A box's eight corners as the scene's vertices.
    Scene scene;
    Mesh box;
    const glm::vec3 center(10.0f, 0.0f, -4.0f), half(3.0f, 1.0f, 2.0f);
    for (int i = 0; i < 8; ++i)
        box.positions.push_back(center + glm::vec3((i & 1) ? half.x : -half.x, (i & 2) ? half.y : -half.y,
                                                   (i & 4) ? half.z : -half.z));
    scene.meshes.push_back(box);
    scene.instances.push_back({0, glm::mat4(1.0f)});
    scene.computeBounds();
    for (const int width : {1067, 300}) {
        const int height = 600;
        const double aspect = double(width) / height;
        OrbitCamera orbit(startCamera(), cube(1.0));
        orbit.orbit(123.0, -17.0);
        orbit.pan(300.0, 100.0, 600);
        const double yaw = orbit.yawRad(), pitch = orbit.pitchRad();
        orbit.frame(scene, aspect);
        EXPECT_NEAR(orbit.yawRad(), yaw, 1e-12);  // framing keeps the viewing direction
        EXPECT_NEAR(orbit.pitchRad(), pitch, 1e-12);
        // Every corner projects inside the view, the corners span kAutoFrameFill of the limiting dimension and
        // leave equal margins on both of its sides.
        const Camera camera = orbit.toCamera();
        glm::dvec2 lo(1e300), hi(-1e300);
        for (const glm::vec3& corner : box.positions) {
            const glm::dvec2 p = toPixel(camera, glm::dvec3(corner), width, height);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        EXPECT_GE(lo.x, 0.0);
        EXPECT_GE(lo.y, 0.0);
        EXPECT_LE(hi.x, width);
        EXPECT_LE(hi.y, height);
        const double fillX = (hi.x - lo.x) / width, fillY = (hi.y - lo.y) / height;
        EXPECT_NEAR(std::max(fillX, fillY), kAutoFrameFill, 1e-6) << fillX << " x " << fillY;
        if (fillX > fillY) EXPECT_NEAR(lo.x, width - hi.x, 1e-6);
        else EXPECT_NEAR(lo.y, height - hi.y, 1e-6);
    }
}
