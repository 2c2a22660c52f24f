// builtin:room under presets/room.json: the point light's cube map puts the pillar's shadow on the floor where a hand
// computation says it falls, on both sides of the cube faces' edges (hard case 9).
#include "gl_fixture.h"

#include "scene/builtin_scenes.h"

#include <cmath>

namespace shadowlab::test {
namespace {

namespace b = shadowlab::builtin;

class RoomPointShadow : public GlTest {};

// By hand: the light L = (0, 3, 0); the pillar spans x, z in [1.2, 1.8] from the floor to the ceiling. The segment from a
// floor point p = (x, 0, z) to L crosses the pillar's vertical extent wherever it crosses its footprint, so p is in
// shadow exactly when the ray from L's foot (0, 0) through (x, z) passes the square [1.2, 1.8]^2 and p lies beyond
// it: the wedge between the directions of the corners (1.8, 1.2) and (1.2, 1.8), atan(1.2 / 1.8) = 33.7 deg to
// 56.3 deg from +x, farther out than the pillar. Cube faces on the floor: -y where |x|, |z| <= 3 (the light's height),
// +x beyond that where x > |z|, +z where z > |x|.
TEST_F(RoomPointShadow, PillarShadowFallsWhereTheHandComputationSaysAcrossCubeFaces) {
    ASSERT_EQ(b::kRoomLight, glm::vec3(0.0f, 3.0f, 0.0f));
    ASSERT_EQ(b::kRoomPillarCenter.x, 1.5f);
    ASSERT_EQ(b::kRoomPillarSize.x, 0.6f);
    Renderer renderer;
    const Scene room = loadBuiltin("room");
    // Straight down from above the room: the ceiling is single-sided and faces down, so the camera sees the floor.
    const Settings settings = topDownShadowView(loadShippedPreset("room"));
    const View view = renderView(renderer, room, settings, 320, 240);
    saveView(view, "room-pillar-shadow");
    ASSERT_TRUE(view.stats.ok) << view.stats.error;

    struct Probe {
        glm::dvec3 p;
        bool shadowed;
        const char* where;
    };
    const Probe probes[] = {
        {{2.5, 0.0, 2.5}, true, "on the diagonal behind the pillar, face -y"},
        {{2.9, 0.0, 2.9}, true, "next to the corner of the -y face"},
        {{4.0, 0.0, 4.0}, true, "on the seam between faces +x and +z"},
        {{4.2, 0.0, 3.2}, true, "face +x, 37 deg: inside the wedge"},
        {{3.2, 0.0, 4.2}, true, "face +z, 53 deg: inside the wedge"},
        {{2.6, 0.0, 2.0}, true, "face -y, 38 deg: inside the wedge"},
        {{4.5, 0.0, 1.5}, false, "face +x, 18 deg: beside the wedge"},
        {{1.5, 0.0, 4.5}, false, "face +z, 72 deg: beside the wedge"},
        {{2.8, 0.0, 1.2}, false, "face -y, 23 deg: beside the wedge"},
        {{0.8, 0.0, 0.8}, false, "between the light's foot and the pillar"},
        {{-3.0, 0.0, 3.0}, false, "the opposite quadrant"},
    };
    for (const Probe& probe : probes) {
        SCOPED_TRACE(probe.where);
        const double red = view.meanRedAround(probe.p, 1);
        ASSERT_GE(red, 0.0) << "off screen";
        if (probe.shadowed)
            EXPECT_LT(red, 40.0);
        else
            EXPECT_GT(red, 215.0);
    }
}

}  // namespace
}  // namespace shadowlab::test
