// Issue 14, reversed-Z: the map really is stored the other way round (near 1, far 0, cleared to 0), the bias report
// and the light volume stay those of the normal convention, and the main pass reads it as the same shadow.
#include "gl_fixture.h"

#include "settings/settings_fields.h"

#include <cmath>

namespace shadowlab::test {
namespace {

class ReversedZMap : public GlTest {};

void set(Settings& s, const char* keyValue) { ASSERT_EQ(applySettingOverride(s, keyValue), "") << keyValue; }

TEST_F(ReversedZMap, StoresOneMinusTheNormalDepthAndClearsToZero) {
    const Scene scene = loadBuiltin("textbook");
    Settings normal = loadShippedPreset("default");
    set(normal, "shadow.depthBias=0");  // D32F's bias step differs between the conventions; the geometry does not
    set(normal, "shadow.slopeScaledDepthBias=0");
    set(normal, "shadow.resolution=256");
    Settings reversed = normal;
    set(reversed, "shadow.reversedZ=true");
    Renderer a, b;
    const View viewA = renderView(a, scene, normal, 160, 120);
    const View viewB = renderView(b, scene, reversed, 160, 120);
    ASSERT_TRUE(viewA.stats.ok && viewB.stats.ok);
    EXPECT_TRUE(viewB.stats.light.reversedZ);
    EXPECT_TRUE(b.shadowMap().reversedZ());
    const std::vector<float> da = a.shadowMap().readDepth(), db = b.shadowMap().readDepth();
    ASSERT_EQ(da.size(), db.size());
    int written = 0, cleared = 0, off = 0;
    for (std::size_t i = 0; i < da.size(); ++i) {
        if (da[i] >= 1.0f) {
            ++cleared;
            off += db[i] != 0.0f;
        } else {
            ++written;
            off += std::abs((1.0 - double(db[i])) - double(da[i])) > 1e-5;
        }
    }
    EXPECT_GT(written, 1000);
    EXPECT_EQ(off, 0) << "of " << written << " written and " << cleared << " cleared texels";
    // The same bias report (receivers nearest / farthest, in world units) and the same volume.
    EXPECT_NEAR(viewA.stats.bias.texelWorldSize, viewB.stats.bias.texelWorldSize, 1e-9);
    EXPECT_NEAR(viewA.stats.bias.constantNear.world, viewB.stats.bias.constantNear.world, 1e-9);
    const glm::dmat4 va = viewA.stats.light.volumeViewProjection(), vb = viewB.stats.light.volumeViewProjection();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(va[c][r], vb[c][r], 1e-9);
}

TEST_F(ReversedZMap, ASpotAndAPointLightShadowTheSamePixels) {
    const Scene scene = loadBuiltin("textbook");
    for (const char* type : {"spot", "point"}) {
        SCOPED_TRACE(type);
        Settings s = topDownShadowView(loadShippedPreset("default"));
        set(s, (std::string("lights.0.type=") + type).c_str());
        set(s, "lights.0.position=3,6,2");
        set(s, "lights.0.direction=-0.5,-1,-0.4");
        set(s, "lights.0.spotConeDeg=120");
        Settings r = s;
        set(r, "shadow.reversedZ=true");
        Renderer a, b;
        const View va = renderView(a, scene, s, 240, 180), vb = renderView(b, scene, r, 240, 180);
        ASSERT_TRUE(va.stats.ok && vb.stats.ok) << va.stats.error << vb.stats.error;
        saveView(vb, std::string("reversed-z-") + type);
        long dark = 0, differ = 0;
        for (std::size_t i = 0; i < va.rgba.size(); i += 4) {
            dark += va.rgba[i] < 40;
            differ += std::abs(int(va.rgba[i]) - int(vb.rgba[i])) > 64;
        }
        EXPECT_GT(dark, 500) << "the cube must cast a shadow for the check to mean anything";
        EXPECT_LT(differ, long(va.rgba.size() / 4 / 500)) << differ << " pixels differ";
    }
}

}  // namespace
}  // namespace shadowlab::test
