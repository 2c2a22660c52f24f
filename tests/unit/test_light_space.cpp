// Light-space math: finite, continuous matrices for every direction (HARD_CASES 1, 14) and an ortho fit that
// contains the scene.
#include "light/light_space.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace shadowlab {
namespace {

Bounds unitBox(glm::vec3 lo, glm::vec3 hi) {
    Bounds b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

LightSpace build(const Settings& s, const Bounds& b, glm::dvec3 origin = glm::dvec3(0.0)) {
    std::string error;
    std::optional<LightSpace> ls = buildLightSpace(s, b, origin, error);
    EXPECT_TRUE(ls.has_value()) << error;
    return ls.value_or(LightSpace{});
}

TEST(LightSpace, BasisIsOrthonormalAndFiniteForEveryDirection) {
    // A dense sphere of directions, plus the poles and tiny tilts around them (HARD_CASES 1).
    std::vector<glm::dvec3> directions = {{0, -1, 0}, {0, 1, 0}, {1e-7, -1, 0}, {-1e-7, -1, 0}, {0, -1, 1e-9},
                                          {1e-7, 1, 0}, {0, 1, -1e-12}, {1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j <= 32; ++j) {
            const double phi = i * 2.0 * M_PI / 64, theta = j * M_PI / 32;
            directions.emplace_back(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        }
    for (const glm::dvec3& d : directions) {
        const glm::dmat3 basis = lightBasis(d);
        const glm::dvec3 right = basis[0], up = basis[1], back = basis[2];
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) ASSERT_TRUE(std::isfinite(basis[c][r])) << d.x << "," << d.y << "," << d.z;
        EXPECT_NEAR(glm::length(right), 1.0, 1e-12);
        EXPECT_NEAR(glm::length(up), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(right, up), 0.0, 1e-12);
        EXPECT_NEAR(glm::dot(back, -glm::normalize(d)), 1.0, 1e-12);
        EXPECT_NEAR(glm::determinant(basis), 1.0, 1e-12);  // right-handed: the map is never mirrored
    }
}

TEST(LightSpace, BasisIsContinuousAcrossStraightDown) {
    // The textbook lookAt(up=(0,1,0)) is NaN at straight down and flips 180 degrees across it; ours must not.
    glm::dmat3 previous = lightBasis({std::sin(-1e-3), -std::cos(-1e-3), 0.0});
    for (double t = -1e-3 + 1e-5; t <= 1e-3 + 1e-12; t += 1e-5) {
        const glm::dmat3 basis = lightBasis({std::sin(t), -std::cos(t), 0.0});
        EXPECT_GT(glm::dot(basis[0], previous[0]), 0.999999) << "right vector jumped at t=" << t;
        EXPECT_GT(glm::dot(basis[1], previous[1]), 0.999999) << "up vector jumped at t=" << t;
        previous = basis;
    }
}

TEST(LightSpace, StraightDownAndUpGiveFiniteMatrices) {
    Settings s;
    const Bounds b = unitBox({-10, 0, -10}, {10, 3, 10});
    for (glm::vec3 d : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0), glm::vec3(1e-7f, -1, 0)}) {
        s.lights[0].direction = d;
        for (LightType type : {LightType::Directional, LightType::Spot}) {
            s.lights[0].type = type;
            const LightSpace ls = build(s, b);
            EXPECT_TRUE(allFinite(ls.view));
            EXPECT_TRUE(allFinite(ls.projection));
        }
    }
}

TEST(LightSpace, OrthoFitContainsEverySceneCorner) {
    Settings s;
    const Bounds b = unitBox({-7, -1, -3}, {9, 4, 12});
    for (glm::vec3 d : {glm::vec3(-0.4f, -1, -0.3f), glm::vec3(0, -1, 0), glm::vec3(1, -0.05f, 0.2f)}) {
        s.lights[0].direction = d;
        const LightSpace ls = build(s, b);
        const glm::dmat4 vp = ls.viewProjection();
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
            const glm::dvec4 clip = vp * glm::dvec4(corner, 1.0);
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_LE(std::abs(clip[axis] / clip.w), 1.0) << "corner " << i << " axis " << axis;
            }
        }
    }
}

TEST(LightSpace, LargeWorldCoordinatesStayPreciseRelativeToTheOrigin) {
    // HARD_CASES 3: the same scene moved by 1e6 must give the same light space relative to its render origin.
    Settings s;
    const Bounds near = unitBox({-85, 0, -85}, {85, 30, 85});
    const glm::vec3 t(1e6f, 0, 1e6f);
    const Bounds far = unitBox(near.min + t, near.max + t);
    const LightSpace a = build(s, near, glm::dvec3(near.center()));
    const LightSpace b = build(s, far, glm::dvec3(far.center()));
    const glm::dmat4 va = a.viewProjection(), vb = b.viewProjection();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(va[c][r], vb[c][r], 1e-9);
}

TEST(LightSpace, DegenerateInputIsRefusedWithAMessage) {
    Settings s;
    const Bounds b = unitBox({-1, -1, -1}, {1, 1, 1});
    std::string error;
    s.lights[0].direction = glm::vec3(0.0f);
    EXPECT_FALSE(buildLightSpace(s, b, glm::dvec3(0.0), error).has_value());
    EXPECT_NE(error.find("light.direction"), std::string::npos);
    s = Settings{};
    s.lights[0].direction = glm::vec3(std::nanf(""), -1, 0);
    error.clear();
    EXPECT_FALSE(buildLightSpace(s, b, glm::dvec3(0.0), error).has_value());
    s = Settings{};
    s.lights[0].projection.autoFit = false;
    s.lights[0].projection.nearPlane = 5.0f;
    s.lights[0].projection.farPlane = 5.0f;
    error.clear();
    EXPECT_FALSE(buildLightSpace(s, b, glm::dvec3(0.0), error).has_value());
    EXPECT_NE(error.find("near"), std::string::npos);
}

TEST(LightSpace, TexelWorldSizeFollowsSizeAndResolution) {
    Settings s;
    s.lights[0].projection.autoFit = false;
    s.lights[0].projection.orthoSize = 100.0f;
    s.lights[0].projection.nearPlane = 0.1f;
    s.lights[0].projection.farPlane = 100.0f;
    s.lights[0].shadow.resolution = 2048;
    const LightSpace ls = build(s, unitBox({-1, -1, -1}, {1, 1, 1}));
    EXPECT_NEAR(ls.texelWorldSize, 100.0 / 2048.0, 1e-12);  // HARD_CASES 7: 0.0488
}

}  // namespace
}  // namespace shadowlab
