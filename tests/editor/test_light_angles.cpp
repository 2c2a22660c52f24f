// The Light panel's azimuth / elevation: where the light comes from, and back to the direction it travels.
#include "editor/light_angles.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace shadowlab::editor {

TEST(LightAngles, ElevationIsTheAngleAboveTheHorizonOfWhereTheLightComesFrom) {
    EXPECT_NEAR(anglesFromDirection({0.0f, -1.0f, 0.0f}).elevationDeg, 90.0f, 1e-4f);  // straight down
    const LightAngles a = anglesFromDirection({-1.0f, -1.0f, 0.0f});                  // from +x, 45 deg up
    EXPECT_NEAR(a.elevationDeg, 45.0f, 1e-4f);
    EXPECT_NEAR(a.azimuthDeg, 0.0f, 1e-4f);
    EXPECT_NEAR(anglesFromDirection({0.0f, -1.0f, -1.0f}).azimuthDeg, 90.0f, 1e-4f);  // from +z
}

TEST(LightAngles, AnglesRoundTripToTheSameDirection) {
    for (const glm::vec3 d : {glm::vec3(-0.4f, -1.0f, -0.3f), glm::vec3(0.7f, -0.2f, 0.1f), glm::vec3(0.0f, -1.0f, 0.2f)}) {
        const glm::vec3 back = directionFromAngles(anglesFromDirection(d));
        EXPECT_NEAR(glm::length(back), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(back, glm::normalize(d)), 0.99999f) << d.x << " " << d.y << " " << d.z;
    }
}

}  // namespace shadowlab::editor
