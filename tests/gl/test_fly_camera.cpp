// The view camera's fly mode and pivot (frame/orbit_camera.h): travel per second whatever the frame rate, at a speed
// that follows the scene's size; mouse look keeps the eye; a picked pivot keeps the eye and faces the point.
#include "frame/orbit_camera.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

using namespace shadowlab;

namespace {

Bounds boxOf(double halfSize) {
    Bounds b;
    b.extend(glm::vec3(float(-halfSize)));
    b.extend(glm::vec3(float(halfSize)));
    return b;
}

OrbitCamera startCamera(double halfSize) {
    Camera c;
    c.position = {0.0, 2.0, 10.0};
    c.target = {0.0, 2.0, 0.0};
    return OrbitCamera(c, boxOf(halfSize));
}

double distance(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b); }

}  // namespace

TEST(FlyCamera, TravelDependsOnSecondsNotOnFrames) {
    OrbitCamera coarse = startCamera(10.0), fine = startCamera(10.0);
    const glm::dvec3 forward(0.0, 0.0, 1.0);
    for (int i = 0; i < 4; ++i) coarse.fly(forward, 0.25);   // 4 frames of 1/4 s
    for (int i = 0; i < 60; ++i) fine.fly(forward, 1.0 / 60.0);  // 60 frames of 1/60 s
    EXPECT_NEAR(distance(coarse.eye(), fine.eye()), 0.0, 1e-9);
    // One second forward at the scene-sized speed, along the view (-z here); the pivot travels along.
    const double speed = coarse.flySpeed();
    EXPECT_NEAR(speed, OrbitCamera::kFlyRadiiPerSecond * boxOf(10.0).radius(), 1e-5);
    EXPECT_NEAR(distance(coarse.eye(), glm::dvec3(0.0, 2.0, 10.0 - speed)), 0.0, 1e-9);
    EXPECT_NEAR(distance(coarse.target(), glm::dvec3(0.0, 2.0, -speed)), 0.0, 1e-9);
}

TEST(FlyCamera, SpeedFollowsTheSceneAndTheFactor) {
    OrbitCamera small = startCamera(1.0), large = startCamera(1000.0);
    EXPECT_NEAR(large.flySpeed() / small.flySpeed(), 1000.0, 1e-3);  // bounds are float
    OrbitCamera fast = startCamera(10.0), slow = startCamera(10.0);
    fast.fly({1.0, 0.0, 0.0}, 0.5, 4.0);  // right, 4x
    slow.fly({1.0, 0.0, 0.0}, 0.5, 1.0);
    EXPECT_NEAR(fast.eye().x, 4.0 * slow.eye().x, 1e-9);
    EXPECT_GT(slow.eye().x, 0.0);  // D moves right (+x looking down -z)
    OrbitCamera up = startCamera(10.0);
    up.fly({0.0, 1.0, 0.0}, 1.0);  // E rises
    EXPECT_GT(up.eye().y, 2.0);
    up.fly({0.0, 0.0, 1.0}, -1.0);  // a clock that went backwards moves nothing
    EXPECT_NEAR(up.eye().z, 10.0, 1e-9);
}

TEST(FlyCamera, LookTurnsAroundTheEye) {
    OrbitCamera c = startCamera(10.0);
    const glm::dvec3 eye = c.eye();
    c.look(100.0, 0.0);  // mouse right: look right
    EXPECT_NEAR(distance(c.eye(), eye), 0.0, 1e-9);
    EXPECT_GT(c.target().x, 0.0);
    c.look(0.0, 50.0);  // mouse down: look down
    EXPECT_NEAR(distance(c.eye(), eye), 0.0, 1e-9);
    EXPECT_LT(c.target().y, eye.y);
}

TEST(FlyCamera, PivotOnAPickedPointKeepsTheEye) {
    OrbitCamera c = startCamera(10.0);
    const glm::dvec3 eye = c.eye();
    const glm::dvec3 point(3.0, 0.0, -2.0);
    c.setPivot(point);
    EXPECT_NEAR(distance(c.eye(), eye), 0.0, 1e-9);
    EXPECT_NEAR(distance(c.target(), point), 0.0, 1e-9);
    // Orbits now turn around the point: it stays where it is, the eye keeps its distance to it.
    c.orbit(80.0, -30.0);
    EXPECT_NEAR(distance(c.target(), point), 0.0, 1e-9);
    EXPECT_NEAR(distance(c.eye(), point), distance(eye, point), 1e-9);
}

TEST(FlyCamera, OrthographicCameraStaysOrthographicAndZoomsBySize) {
    Camera ortho;
    ortho.position = {0.0, 30.0, 0.001};
    ortho.target = {0.0, 0.0, 0.0};
    ortho.orthoHalfHeight = 12.0;
    OrbitCamera c(ortho, boxOf(10.0));
    EXPECT_NEAR(c.toCamera().orthoHalfHeight, 12.0, 1e-12);
    c.zoom(1.0);
    EXPECT_NEAR(c.toCamera().orthoHalfHeight, 12.0 * OrbitCamera::kZoomPerWheelStep, 1e-9);
    // F frames it by its size too: the height a perspective view of its fov shows at the pivot's depth.
    Scene scene;
    scene.bounds = boxOf(10.0);
    c.frame(scene, 1.0);
    EXPECT_NEAR(c.toCamera().orthoHalfHeight, c.distance() * std::tan(glm::radians(45.0) * 0.5), 1e-9);
}
