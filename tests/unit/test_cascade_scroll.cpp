// The scrolling cascade cache's geometry (views/cascade_scroll.h): what tells a whole-texel scroll from any other
// change of a cascade, the strips it exposes, and the pages whose matrices do not depend on where the cascade stands.
#include "light/light_space.h"
#include "views/cascade_scroll.h"

#include <gtest/gtest.h>

#include <glm/ext/vector_double4.hpp>

namespace shadowlab {
namespace {

constexpr int kN = 512;
constexpr double kHalf = 16.0;  // a texel of 1/16
constexpr double kTexel = 2.0 * kHalf / kN;

// A stable cascade centred on global texel (kx, ky), as cascade_views.cpp builds it.
LightSpace cascadeAt(long long kx, long long ky) {
    const double depth = 50.0;
    LightSettings light;
    light.shadow.resolution = kN;
    const glm::dvec3 direction = glm::normalize(glm::dvec3(-0.25, -0.55, -0.8));
    LightSpace s = orthoLightSpace(light, direction, glm::dvec3(0.0), kHalf, 0.0, 2.0 * depth);
    s.view[3] = glm::dvec4(-double(kx) * kTexel, -double(ky) * kTexel, -depth, 1.0);
    return s;
}

// The texel (x, y) of a map a world point falls in.
glm::dvec2 texelOf(const LightSpace& s, const glm::dvec3& world) {
    const glm::dvec4 clip = s.viewProjection() * glm::dvec4(world, 1.0);
    return (glm::dvec2(clip) * 0.5 + 0.5) * double(s.resolution);
}

TEST(CascadeScroll, AWholeTexelMoveIsAShiftThatMovesEveryPointByIt) {
    const LightSpace before = cascadeAt(100, -40), now = cascadeAt(97, -39);
    const CascadeScroll scroll = cascadeScroll(before.viewProjection(), now.viewProjection(), kN);
    ASSERT_TRUE(scroll.shift) << scroll.why;
    EXPECT_EQ(*scroll.shift, (TexelShift{3, -1}));
    const glm::dvec3 world(6.1, 2.0, -3.3);
    const glm::dvec2 moved = texelOf(now, world) - texelOf(before, world);
    EXPECT_NEAR(moved.x, 3.0, 1e-9);
    EXPECT_NEAR(moved.y, -1.0, 1e-9);
    EXPECT_EQ(describeScroll(*scroll.shift, kN), "scrolled 3,-1 texels: 99.2 % reused");
}

TEST(CascadeScroll, OtherChangesAreNoScrollAndSayWhy) {
    const LightSpace before = cascadeAt(0, 0);
    LightSpace deeper = cascadeAt(2, 0);
    deeper.view[3][2] -= 1.0;  // the scene's bounds grew: every texel's depth would change
    EXPECT_EQ(cascadeScroll(before.viewProjection(), deeper.viewProjection(), kN).why,
              "its depth range or the light's direction changed");
    LightSpace half = before;
    half.view[3][0] -= 0.5 * kTexel;
    EXPECT_EQ(cascadeScroll(before.viewProjection(), half.viewProjection(), kN).why,
              "it moved by -0.5 texels, not whole ones");
    LightSpace bigger = before;
    bigger.projection[0][0] *= 0.5;
    bigger.projection[1][1] *= 0.5;
    EXPECT_EQ(cascadeScroll(before.viewProjection(), bigger.viewProjection(), kN).why,
              "its size or the light's direction changed");
    EXPECT_EQ(cascadeScroll(before.viewProjection(), cascadeAt(kN, 0).viewProjection(), kN).why,
              "it moved by a whole map or more");
}

TEST(CascadeScroll, TheExposedStripsAndTheCopiedOverlapTileTheMap) {
    for (const TexelShift s : {TexelShift{3, -1}, TexelShift{-5, 0}, TexelShift{0, 7}, TexelShift{0, 0}}) {
        long long area = scrollTarget(s, kN).area();
        EXPECT_EQ(scrollSource(s, kN).area(), area);
        const std::vector<TexelRect> strips = exposedStrips(s, kN);
        for (std::size_t i = 0; i < strips.size(); ++i) {
            area += strips[i].area();
            EXPECT_FALSE(strips[i].overlaps(scrollTarget(s, kN)));
            for (std::size_t j = i + 1; j < strips.size(); ++j) EXPECT_FALSE(strips[i].overlaps(strips[j]));
        }
        EXPECT_EQ(area, (long long)kN * kN) << s.dx << "," << s.dy;
    }
}

// What makes a scrolled map equal a whole one bit for bit: a page's matrix is the same, whichever cascade asks for
// it, and it puts a world point in the page texel the cascade's map holds it at.
TEST(CascadeScroll, APagesMatrixDependsOnThePageAloneAndAgreesWithTheCascade) {
    const LightSpace a = cascadeAt(100, -40), b = cascadeAt(97, -39);
    const std::vector<CascadePage> pagesA = cascadePages(a, {0, 0, kN, kN});
    ASSERT_EQ(pagesA.size(), 25u) << "a map off the page grid meets 5 x 5 pages of a quarter of its size";
    const std::vector<CascadePage> pagesB = cascadePages(b, {0, 0, kN, kN});
    int shared = 0;
    for (const CascadePage& pa : pagesA)
        for (const CascadePage& pb : pagesB)
            if (pa.space.view[3] == pb.space.view[3]) {
                ++shared;
                EXPECT_EQ(glm::mat4(pa.space.viewProjection()), glm::mat4(pb.space.viewProjection()));
            }
    EXPECT_EQ(shared, 25);
    long long covered = 0;
    const glm::dvec3 world(3.3, 1.0, -2.7);
    const glm::dvec2 inMap = texelOf(a, world);
    for (const CascadePage& p : pagesA) {
        EXPECT_EQ(p.space.resolution, kN / kPagesAcross);
        EXPECT_EQ(p.inPage.x1 - p.inPage.x0, p.inMap.x1 - p.inMap.x0);
        covered += p.inMap.area();
        const glm::dvec2 inPage = texelOf(p.space, world);
        const glm::dvec2 offset = inMap - inPage;  // the page's texel 0 in the map
        EXPECT_NEAR(offset.x, double(p.inMap.x0 - p.inPage.x0), 1e-9);
        EXPECT_NEAR(offset.y, double(p.inMap.y0 - p.inPage.y0), 1e-9);
    }
    EXPECT_EQ(covered, (long long)kN * kN);
    EXPECT_TRUE(cascadePages(a, {0, 0, 0, 0}).empty());
}

}  // namespace
}  // namespace shadowlab
