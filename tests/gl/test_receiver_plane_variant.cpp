// Issue 14, receiver-plane depth bias: it costs nothing where it cannot act. Only a filter whose taps spread (PCF,
// Poisson) on a directional or spot light compiles RECEIVER_PLANE in; the shadow map itself never re-renders for it.
#include "gl_fixture.h"

#include "settings/settings_fields.h"

#include <algorithm>

namespace shadowlab::test {
namespace {

class ReceiverPlaneVariant : public GlTest {};

void set(Settings& s, const std::string& keyValue) { ASSERT_EQ(applySettingOverride(s, keyValue), "") << keyValue; }

bool hasDefine(const FrameStats& stats, const std::string& define) {
    return std::any_of(stats.mainVariants.begin(), stats.mainVariants.end(),
                       [&](const std::string& v) { return v.find(define) != std::string::npos; });
}

TEST_F(ReceiverPlaneVariant, OnlySpreadingFiltersOnDirectionalAndSpotLightsCompileItIn) {
    const Scene scene = loadBuiltin("textbook");
    struct Case {
        const char* filter;
        const char* type;
        bool expected;
    };
    for (const Case& c : {Case{"pcf", "directional", true}, Case{"poisson", "spot", true}, Case{"point", "directional", false},
                          Case{"hardware2x2", "spot", false}, Case{"pcf", "point", false}}) {
        SCOPED_TRACE(std::string(c.filter) + " " + c.type);
        Settings s = loadShippedPreset("default");
        set(s, std::string("filter.kind=") + c.filter);
        set(s, std::string("lights.0.type=") + c.type);
        set(s, "lights.0.position=3,6,2");
        set(s, "shadow.receiverPlaneBias=false");  // on in the default preset
        Renderer renderer;
        const View off = renderView(renderer, scene, s, 64, 48);
        set(s, "shadow.receiverPlaneBias=true");
        const View on = renderView(renderer, scene, s, 64, 48);
        ASSERT_TRUE(off.stats.ok && on.stats.ok) << on.stats.error;
        EXPECT_FALSE(hasDefine(off.stats, "RECEIVER_PLANE"));
        EXPECT_EQ(hasDefine(on.stats, "RECEIVER_PLANE"), c.expected);
        if (!c.expected) EXPECT_EQ(on.stats.mainVariants, off.stats.mainVariants) << "no cost where it cannot act";
        EXPECT_FALSE(on.stats.shadowPass.ran) << "the map does not depend on it: " << on.stats.shadowPass.reason;
    }
}

}  // namespace
}  // namespace shadowlab::test
