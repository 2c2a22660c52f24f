// Issue 21: the moments pass of the moments techniques (renderer/shadow/moments_pass.*): it runs only for a technique
// that needs it and only for views whose map (or moments settings) changed; what it stores equals its CPU mirror
// (shading/filters/moments_mirror.h) for every technique and precision; EVSM's largest exponents store no Inf/NaN; a
// point light's cube faces get moments too (the room's pillar shadow under VSM), blurred across their edges without a
// seam, as the mirror blurs them.
#include "gl_fixture.h"

#include "shading/filters/cube_face_frame.h"
#include "shading/filters/filter_technique.h"
#include "shading/filters/moments_mirror.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadowlab::test {
namespace {

class MomentsPassTest : public GlTest {};

Settings withTechnique(Settings s, FilterKind kind, int bits = 32, int resolution = 256) {
    s.filter.kind = kind;
    s.filter.momentBits = bits;
    s.lights[0].shadow.resolution = resolution;
    return s;
}

TEST_F(MomentsPassTest, RunsOnlyForAMomentsTechniqueAndOnlyWhenAViewChanged) {
    const Scene scene = loadBuiltin("textbook");
    Renderer renderer;
    Settings s = withTechnique(topDownShadowView(loadShippedPreset("default")), FilterKind::Pcf);
    View v = renderView(renderer, scene, s, 160, 120);
    EXPECT_TRUE(v.stats.shadowPass.ran);
    EXPECT_FALSE(v.stats.momentsPass.ran) << v.stats.momentsPass.reason;
    EXPECT_FALSE(v.stats.blurPass.ran);
    EXPECT_NE(v.stats.momentsPass.reason.find("filter.kind pcf compares depth"), std::string::npos);

    // Switching to VSM: the map is not re-rendered (its depth did not change), its moments are made.
    s.filter.kind = FilterKind::Vsm;
    v = renderView(renderer, scene, s, 160, 120);
    EXPECT_TRUE(v.stats.momentsPass.ran);
    EXPECT_TRUE(v.stats.blurPass.ran);
    EXPECT_NE(v.stats.momentsPass.reason.find("moments settings changed"), std::string::npos) << v.stats.momentsPass.reason;

    // The same frame again: no view re-rendered, no moments pass, no blur.
    v = renderView(renderer, scene, s, 160, 120);
    EXPECT_FALSE(v.stats.shadowPass.ran);
    EXPECT_FALSE(v.stats.momentsPass.ran) << v.stats.momentsPass.reason;
    EXPECT_FALSE(v.stats.blurPass.ran);

    // A new blur width redoes the moments, not the shadow pass; a light move redoes both.
    s.filter.blurWidth = 9.0f;
    v = renderView(renderer, scene, s, 160, 120);
    EXPECT_FALSE(v.stats.shadowPass.ran);
    EXPECT_TRUE(v.stats.momentsPass.ran);
    s.lights[0].direction.x += 0.05f;
    v = renderView(renderer, scene, s, 160, 120);
    EXPECT_TRUE(v.stats.shadowPass.ran);
    EXPECT_TRUE(v.stats.momentsPass.ran);
    EXPECT_NE(v.stats.momentsPass.reason.find("map re-rendered"), std::string::npos) << v.stats.momentsPass.reason;
    // Width 1: moments, no blur.
    s.filter.blurWidth = 1.0f;
    v = renderView(renderer, scene, s, 160, 120);
    EXPECT_TRUE(v.stats.momentsPass.ran);
    EXPECT_FALSE(v.stats.blurPass.ran);
}

TEST_F(MomentsPassTest, StoredMomentsEqualTheCpuMirrorForEveryTechniqueAndPrecision) {
    const Scene scene = loadBuiltin("textbook");
    for (FilterKind kind : {FilterKind::Vsm, FilterKind::Evsm2, FilterKind::Evsm4, FilterKind::Msm})
        for (int bits : {16, 32})
            for (bool reversed : {false, true})
            for (bool spot : {false, true}) {
                Settings s = withTechnique(loadShippedPreset("default"), kind, bits, 128);
                s.lights[0].shadow.reversedZ = reversed;
                if (spot) {  // a perspective view: moments of its linear depth
                    s.lights[0].type = LightType::Spot;
                    s.lights[0].position = glm::vec3(3.0f, 6.0f, 2.0f);
                    s.lights[0].direction = glm::vec3(-0.5f, -1.0f, -0.4f);
                    s.lights[0].spotConeDeg = 120.0f;
                }
                s.filter.blurWidth = 4.5f;  // fractional ends
                s.filter.positiveExponent = 30.0f;  // clamped at 16 bits
                Renderer renderer;
                const View v = renderView(renderer, scene, s, 64, 48);
                ASSERT_TRUE(v.stats.ok) << v.stats.error;
                const FilterTechnique& t = filterTechnique(kind);
                SCOPED_TRACE(std::string(t.name) + " " + std::to_string(bits) + (reversed ? " reversed-Z" : "") +
                             (spot ? " spot" : ""));
                const ShadowMap& map = renderer.shadowMap();
                const std::vector<glm::vec4> gpu = renderer.viewMoments(ShadowViewId{0}, 0, 0, 128, 128);
                const LightSpace& space = v.stats.views.at(0).space;
                ASSERT_EQ(space.perspective, spot);
                const MomentDepthConvention convention{reversed, spot, float(space.nearPlane), float(space.farPlane)};
                const std::vector<glm::vec4> cpu = momentsOfDepth(map.readDepth(), 128, convention, s.filter, 4.5);
                ASSERT_EQ(gpu.size(), cpu.size());
                int off = 0;
                double worst = 0.0;
                for (std::size_t i = 0; i < cpu.size(); ++i)
                    for (int c = 0; c < t.moments->channels; ++c) {
                        // One storage step (fp16: 2^-10 relative, unorm16: 2 / 65535) plus float rounding.
                        const double scale = std::max(std::abs(double(cpu[i][c])), 1e-3);
                        const double d = std::abs(double(gpu[i][c]) - double(cpu[i][c])) / scale;
                        worst = std::max(worst, d);
                        off += d > (bits == 16 ? 3e-3 : 1e-4) && std::abs(gpu[i][c] - cpu[i][c]) > 4.0f / 65535.0f;
                    }
                EXPECT_EQ(off, 0) << "worst relative difference " << worst;
                bool anyFinite = true;
                for (const glm::vec4& m : gpu) anyFinite = anyFinite && std::isfinite(m.x) && std::isfinite(m.y);
                EXPECT_TRUE(anyFinite);
            }
}

TEST_F(MomentsPassTest, PerspectiveViewsStoreLinearDepthBetweenNearAndFar) {
    // A spot light straight down over open floor (only the floor in its 30-degree cone): every texel's stored first
    // moment (VSM: the depth itself) is the floor's distance along the axis, 6, normalised by near and far, not its
    // window depth (which crowds near 1).
    const Scene scene = loadBuiltin("textbook");
    Settings s = withTechnique(loadShippedPreset("default"), FilterKind::Vsm, 32, 128);
    s.lights[0].type = LightType::Spot;
    s.lights[0].position = glm::vec3(5.0f, 6.0f, 5.0f);
    s.lights[0].direction = glm::vec3(0.0f, -1.0f, 0.0f);
    s.lights[0].spotConeDeg = 30.0f;
    s.filter.blurWidth = 1.0f;
    Renderer renderer;
    const View v = renderView(renderer, scene, s, 64, 48);
    ASSERT_TRUE(v.stats.ok) << v.stats.error;
    const LightSpace& space = v.stats.views.at(0).space;
    ASSERT_TRUE(space.perspective);
    const double expected = (6.0 - space.nearPlane) / (space.farPlane - space.nearPlane);
    for (const glm::ivec2 texel : {glm::ivec2(0, 0), glm::ivec2(64, 64), glm::ivec2(127, 20)}) {
        const glm::vec4 m = renderer.viewMoments(ShadowViewId{0}, texel.x, texel.y, 1, 1).at(0);
        EXPECT_NEAR(m.x, expected, 1e-3) << "texel " << texel.x << "," << texel.y << " near " << space.nearPlane
                                         << " far " << space.farPlane;
        EXPECT_NEAR(m.y, m.x * m.x, 1e-5);
    }
}

TEST_F(MomentsPassTest, MipLevelsAreBuiltOnlyWhenAskedAndOnlyWhenTheMomentsChangedAndEqualTheCpuMirror) {
    const Scene scene = loadBuiltin("textbook");
    for (FilterKind kind : {FilterKind::Vsm, FilterKind::Msm})
        for (int bits : {16, 32}) {
            Settings s = withTechnique(loadShippedPreset("default"), kind, bits, 128);
            SCOPED_TRACE(std::string(filterTechnique(kind).name) + " " + std::to_string(bits));
            Renderer renderer;
            View v = renderView(renderer, scene, s, 64, 48);
            EXPECT_FALSE(v.stats.mipsPass.ran);
            EXPECT_NE(v.stats.mipsPass.reason.find("filter.momentMips is off"), std::string::npos);
            s.filter.momentMips = true;
            v = renderView(renderer, scene, s, 64, 48);
            ASSERT_TRUE(v.stats.ok) << v.stats.error;
            EXPECT_TRUE(v.stats.mipsPass.ran);
            EXPECT_NE(v.stats.mipsPass.reason.find("7 levels below the map"), std::string::npos) << v.stats.mipsPass.reason;
            // Each level from the GPU's level below (the mean of 2x2 holding a caster, stored at the precision), down
            // to 1x1; level 1 from the unblurred moments (the mips pass runs before the blur).
            const LightSpace& space = v.stats.views.at(0).space;
            const std::vector<glm::vec4> unblurred =
                momentsOfDepth(renderer.shadowMap().readDepth(), 128, {false, false, float(space.nearPlane),
                                                                       float(space.farPlane)}, s.filter, 1.0);
            // The sun's map holds "no caster" texels beside the scene (the far plane's moments), which no level mixes in.
            EXPECT_TRUE(std::any_of(unblurred.begin(), unblurred.end(), [&](const glm::vec4& m) {
                return isEmptyMoments(m, emptyMoments(s.filter));
            }));
            for (int level = 1, size = 64; size >= 1; ++level, size /= 2) {
                const std::vector<glm::vec4> below =
                    level == 1 ? unblurred : renderer.viewMoments(ShadowViewId{0}, 0, 0, 2 * size, 2 * size, level - 1);
                const std::vector<glm::vec4> gpu = renderer.viewMoments(ShadowViewId{0}, 0, 0, size, size, level);
                const std::vector<glm::vec4> cpu = momentsMipLevel(below, 2 * size, s.filter);
                ASSERT_EQ(gpu.size(), cpu.size());
                // Level 1's mirror starts from the CPU's conversion (the GPU's unblurred level 0 is blurred in place
                // after): one more storage step of difference (as StoredMomentsEqualTheCpuMirror... allows).
                const float relative = bits == 16 ? (level == 1 ? 3e-3f : 1e-3f) : (level == 1 ? 1e-5f : 1e-6f);
                const float absolute = bits == 16 ? (level == 1 ? 4.0f : 2.0f) / 65535.0f : 1e-7f;
                int off = 0;
                for (std::size_t i = 0; i < cpu.size(); ++i)
                    for (int c = 0; c < filterTechnique(kind).moments->channels; ++c)
                        off += std::abs(gpu[i][c] - cpu[i][c]) > relative * std::abs(cpu[i][c]) + absolute;
                EXPECT_EQ(off, 0) << "level " << level;
            }
            // Nothing changed: no moments, no mips.
            v = renderView(renderer, scene, s, 64, 48);
            EXPECT_FALSE(v.stats.mipsPass.ran) << v.stats.mipsPass.reason;
            // A light move: the map, its moments and their mips again.
            s.lights[0].direction.x += 0.05f;
            v = renderView(renderer, scene, s, 64, 48);
            EXPECT_TRUE(v.stats.mipsPass.ran);
        }
}

TEST_F(MomentsPassTest, EvsmAtTheLargestExponentStoresNoInfOrNan) {
    const Scene scene = loadBuiltin("textbook");
    for (int bits : {16, 32}) {
        Settings s = withTechnique(loadShippedPreset("default"), FilterKind::Evsm4, bits, 128);
        s.filter.positiveExponent = s.filter.negativeExponent = 42.0f;  // clamped to 5.54 at 16 bits
        Renderer renderer;
        const View v = renderView(renderer, scene, s, 64, 48);
        ASSERT_TRUE(v.stats.ok) << v.stats.error;
        bool warned = false;
        for (const std::string& w : v.stats.warnings) warned = warned || w.rfind("filter.positiveExponent 42", 0) == 0;
        EXPECT_EQ(warned, bits == 16) << bits;
        int nonFinite = 0;
        for (const glm::vec4& m : renderer.viewMoments(ShadowViewId{0}, 0, 0, 128, 128))
            for (int c = 0; c < 4; ++c) nonFinite += !std::isfinite(m[c]);
        EXPECT_EQ(nonFinite, 0) << bits << " bits";
        EXPECT_TRUE(v.stats.momentsPass.ran);
    }
}

TEST_F(MomentsPassTest, PointLightsCubeFacesGetMomentsToo) {
    Renderer renderer;
    const Scene room = loadBuiltin("room");
    Settings settings = topDownShadowView(loadShippedPreset("room"));
    settings.filter.kind = FilterKind::Vsm;
    settings.filter.blurWidth = 3.0f;
    const View view = renderView(renderer, room, settings, 320, 240);
    saveView(view, "room-pillar-shadow-vsm");
    ASSERT_TRUE(view.stats.ok) << view.stats.error;
    EXPECT_TRUE(view.stats.momentsPass.ran);
    // The pillar's wedge (test_room_point_shadow.cpp's hand computation) across the -y, +x and +z faces.
    EXPECT_LT(view.meanRedAround({2.5, 0.0, 2.5}, 1), 60.0);
    EXPECT_LT(view.meanRedAround({4.2, 0.0, 3.2}, 1), 60.0);
    EXPECT_LT(view.meanRedAround({3.2, 0.0, 4.2}, 1), 60.0);
    EXPECT_GT(view.meanRedAround({4.5, 0.0, 1.5}, 1), 200.0);
    EXPECT_GT(view.meanRedAround({-3.0, 0.0, 3.0}, 1), 200.0);
}

// builtin:room's point light (lights.0, a cube of `resolution`^2 faces) under a moments technique, its faces' moments
// as stored and the depths they were made from.
struct RoomCube {
    std::array<std::vector<float>, 6> depth;
    CubeMoments gpu;
    MomentDepthConvention convention;
    std::string momentsReason;  // the frame's moments pass: which faces it made and why
};
RoomCube roomCube(Renderer& renderer, const Settings& settings) {
    const View v = renderView(renderer, loadBuiltin("room"), settings, 64, 48);
    EXPECT_TRUE(v.stats.ok) << v.stats.error;
    RoomCube c;
    const int res = settings.lights[0].shadow.resolution;
    for (int f = 0; f < 6; ++f) {
        c.depth[std::size_t(f)] = renderer.viewMap(0, f)->readDepth();
        c.gpu[std::size_t(f)] = renderer.viewMoments({0, ShadowViewKind::CubeFace, f}, 0, 0, res, res);
    }
    const LightSpace& space = v.stats.views.at(0).space;
    c.convention = {space.reversedZ, true, float(space.nearPlane), float(space.farPlane)};
    c.momentsReason = v.stats.momentsPass.reason;
    return c;
}

// Texels along the cube's edges (corners left out) whose first moment steps across the edge by more than 3x the
// largest step between neighbouring texels on either side (inward, and along the edge), plus a float step: where a
// blur stops at a face's edge, a smooth depth (a floor's ramp, a shadow's blurred edge) turns into a step there.
// (Not 1x: each face stores depth along its own axis, so the field has a kink at the edge; at 2x the cross-face blur
// leaves 4 of 3,048 texels here, at 3x none, while the per-face blur has 2,220.)
int cubeSeamTexels(const CubeMoments& m, int res) {
    const auto at = [&](const CubeTexel& t) { return double(m[std::size_t(t.face)][std::size_t(t.y * res + t.x)].x); };
    int seams = 0;
    for (int face = 0; face < 6; ++face)
        for (const glm::ivec2 out : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)})
            for (int along = 1; along < res - 1; ++along) {
                const glm::ivec2 a = out.x != 0 ? glm::ivec2(out.x > 0 ? res - 1 : 0, along)
                                                : glm::ivec2(along, out.y > 0 ? res - 1 : 0);
                const glm::ivec2 side(out.y, out.x);
                // This face's texel at the edge and its neighbours; the texels across the edge and theirs.
                const auto here = [&](glm::ivec2 t) { return at({face, t.x, t.y}); };
                const auto across = [&](glm::ivec2 t) { return at(*seamlessTexel(face, t.x, t.y, res)); };
                const glm::ivec2 b = a + out;
                const double steps = std::max({std::abs(here(a) - here(a - out)), std::abs(here(a) - here(a + side)),
                                               std::abs(here(a) - here(a - side)), std::abs(across(b) - across(b + out)),
                                               std::abs(across(b) - across(b + side)),
                                               std::abs(across(b) - across(b - side))});
                seams += std::abs(here(a) - across(b)) > 3.0 * steps + 1e-5;
            }
    return seams;
}

TEST_F(MomentsPassTest, APointLightsCubeIsBlurredAcrossItsFacesEdgesWithoutASeam) {
    // The room's pillar and table shadows cross the cube's edges on the floor and the walls. Each face's blur used
    // to stop at the face's edge (its own edge texels repeated): there the blurred depth stepped, and VSM's shadow
    // with it. Now a tap beyond an edge reads the neighbouring face by direction, in the lookups' cube-face frame.
    Settings s = loadShippedPreset("room");
    s.filter.kind = FilterKind::Vsm;
    s.filter.blurWidth = 9.0f;
    const int res = 128;
    s.lights[0].shadow.resolution = res;
    Renderer renderer;
    const RoomCube cube = roomCube(renderer, s);
    // The same depths blurred face by face with the edge repeated (the 2D views' blur) show the seam: the measure
    // finds it.
    CubeMoments perFace;
    for (int f = 0; f < 6; ++f)
        perFace[std::size_t(f)] = momentsOfDepth(cube.depth[std::size_t(f)], res, cube.convention, s.filter, s.filter.blurWidth);
    const int before = cubeSeamTexels(perFace, res), after = cubeSeamTexels(cube.gpu, res);
    std::printf("room, VSM, 9-texel blur, 128^2 faces: %d of %d edge texels step across the edge blurred face by face, "
                "%d as stored\n", before, 24 * (res - 2), after);
    EXPECT_GT(before, 24 * (res - 2) / 2);
    EXPECT_EQ(after, 0);
}

TEST_F(MomentsPassTest, AFaceDrawnLaterRedoesItsNeighboursBlur) {
    // The camera looks along +x from beside the room's light: the -x face's volume misses its view and is not drawn.
    // Turned to -x, that face is drawn; the faces not drawn again whose blur reads it across their edges are made
    // again (from their depths), and the cube equals the mirror of the six faces' depths as they are now.
    Settings s = loadShippedPreset("room");
    s.filter.kind = FilterKind::Vsm;
    s.filter.blurWidth = 7.0f;
    const int res = 64;
    s.lights[0].shadow.resolution = res;
    s.camera.autoFrame = false;
    s.camera.position = {0.5f, 2.0f, 0.0f};
    s.camera.target = {5.0f, 1.0f, 0.0f};
    Renderer renderer;
    const RoomCube first = roomCube(renderer, s);
    ASSERT_EQ(first.momentsReason.find("light 0 -X (map re-rendered)"), std::string::npos) << first.momentsReason;
    s.camera.target = {-5.0f, 1.0f, 0.0f};
    const RoomCube cube = roomCube(renderer, s);
    EXPECT_NE(cube.momentsReason.find("light 0 -X (map re-rendered)"), std::string::npos) << cube.momentsReason;
    for (const char* neighbour : {"+Y", "-Y"})  // not drawn again (llvmpipe: +-z were, their volumes now seen)
        EXPECT_NE(cube.momentsReason.find(std::string("light 0 ") + neighbour + " (a neighbouring face changed)"),
                  std::string::npos)
            << cube.momentsReason;
    const CubeMoments cpu = momentsOfCube(cube.depth, res, cube.convention, s.filter, 7.0);
    for (int f = 0; f < 6; ++f) {
        int off = 0;
        for (std::size_t i = 0; i < cpu[std::size_t(f)].size(); ++i)
            off += std::abs(cube.gpu[std::size_t(f)][i].x - cpu[std::size_t(f)][i].x) > 1e-4f * std::abs(cpu[std::size_t(f)][i].x) + 1e-6f;
        EXPECT_EQ(off, 0) << "face " << f;
    }
}

TEST_F(MomentsPassTest, PointLightCubesStoreTheCpuMirrorsBlurAcrossFaces) {
    // Every face of the cube, edges and corners included, equals momentsOfCube (shading/filters/moments_mirror.h):
    // each pass's taps by direction to the nearest texel of the face they reach, stored at the precision. A coarse
    // cube (64^2) and a wide blur: taps reach 4 texels beyond an edge, where the neighbour's texels grow narrower.
    for (const auto& [kind, bits] : {std::pair{FilterKind::Vsm, 32}, std::pair{FilterKind::Evsm4, 16},
                                     std::pair{FilterKind::Msm, 16}, std::pair{FilterKind::Msm, 32}}) {
        Settings s = loadShippedPreset("room");
        s.filter.kind = kind;
        s.filter.momentBits = bits;
        s.filter.blurWidth = 8.5f;  // fractional ends
        const int res = 64;
        s.lights[0].shadow.resolution = res;
        SCOPED_TRACE(std::string(filterTechnique(kind).name) + " " + std::to_string(bits));
        Renderer renderer;
        const RoomCube cube = roomCube(renderer, s);
        const CubeMoments cpu = momentsOfCube(cube.depth, res, cube.convention, s.filter, 8.5);
        for (int f = 0; f < 6; ++f) {
            ASSERT_EQ(cube.gpu[std::size_t(f)].size(), cpu[std::size_t(f)].size());
            int off = 0;
            double worst = 0.0;
            for (std::size_t i = 0; i < cpu[std::size_t(f)].size(); ++i)
                for (int c = 0; c < filterTechnique(kind).moments->channels; ++c) {
                    const float g = cube.gpu[std::size_t(f)][i][c], m = cpu[std::size_t(f)][i][c];
                    const double d = std::abs(double(g) - double(m)) / std::max(std::abs(double(m)), 1e-3);
                    worst = std::max(worst, d);
                    off += d > (bits == 16 ? 3e-3 : 1e-4) && std::abs(g - m) > 4.0f / 65535.0f;
                }
            EXPECT_EQ(off, 0) << "face " << f << ": worst relative difference " << worst;
        }
    }
}

}  // namespace
}  // namespace shadowlab::test
