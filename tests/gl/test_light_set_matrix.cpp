// Issue 19, "no crash on any light set": a matrix of light sets (directional, spot and point lights mixed; map
// resolutions, formats and reversed-Z differing between lights, so the main pass reads several 2D map arrays beside a
// cube-map array; every filter) renders headless on llvmpipe, and in every frame each light's shadow factor is the one
// it has alone: the shadow view (the mean S of the lights that reach a pixel) equals the mean of the lights rendered
// one at a time. Mesa 22.3's LLVM 15 crashed compiling the main pass of such sets (a sampler array indexed by a
// uniform value beside a cube array); a wrong map chosen for a light would show here as a different S.
#include "gl_fixture.h"
#include "light_alone.h"

#include "scene/builtin_scenes.h"
#include "settings/settings_fields.h"

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace shadowlab::test {
namespace {

class LightSetMatrix : public GlTest {};

void set(Settings& s, const std::string& keyValue) { ASSERT_EQ(applySettingOverride(s, keyValue), "") << keyValue; }

struct LightSetCase {
    std::string name;
    std::vector<std::string> overrides;  // on the courtyard preset: 0 sun, 1 and 2 spots, 3 point lantern
};

std::vector<LightSetCase> lightSets() {
    return {
        {"sun-512-beside-2048-spots", {"lights.0.shadow.resolution=512", "filter.kind=pcf", "filter.kernel=3"}},
        {"every-format", {"lights.0.shadow.depthFormat=d16", "lights.1.shadow.depthFormat=d24",
                          "lights.2.shadow.resolution=1024", "filter.kind=point"}},
        {"reversed-z-mixed", {"lights.0.shadow.reversedZ=true", "lights.2.shadow.reversedZ=true",
                              "lights.3.shadow.reversedZ=true", "lights.1.shadow.resolution=256",
                              "filter.kind=hardware2x2"}},
        {"two-point-arrays", {"lights.2.type=point", "lights.2.position=2,3,2", "lights.3.shadow.resolution=256",
                              "filter.kind=poisson"}},
        {"receiver-plane-wide-kernel", {"lights.0.shadow.receiverPlaneBias=true", "lights.1.shadow.resolution=512",
                                        "lights.1.shadow.receiverPlaneBias=true", "filter.kind=pcf",
                                        "filter.kernel=5"}},
        {"spots-only-three-arrays", {"lights.0.type=spot", "lights.0.position=0,9,0", "lights.0.direction=0,-1,0", "lights.0.spotConeDeg=120",
                                     "lights.0.shadow.resolution=512", "lights.1.shadow.depthFormat=d16",
                                     "lights.3.castsShadows=false", "filter.kind=pcf", "filter.kernel=1"}},
    };
}

TEST_F(LightSetMatrix, EveryMixedLightSetRendersAndEachLightKeepsItsOwnShadow) {
    const Scene scene = loadBuiltin("courtyard");
    const std::optional<Settings> preset = loadShippedPreset("courtyard");
    constexpr int kWidth = 200, kHeight = 150;
    for (const LightSetCase& c : lightSets()) {
        SCOPED_TRACE(c.name);
        Settings s = *preset;
        set(s, "view=shadow");
        for (const std::string& o : c.overrides) set(s, o);
        Renderer renderer;
        const View all = renderView(renderer, scene, s, kWidth, kHeight);
        ASSERT_TRUE(all.stats.ok) << all.stats.error;
        saveView(all, "light-set-" + c.name);

        // Each light alone: its S (0 where it does not reach) and where it reaches (castsShadows off: 1 there).
        const std::size_t count = s.lights.size();
        std::vector<double> sum(std::size_t(kWidth) * kHeight, 0.0), reaching(sum.size(), 0.0);
        for (std::size_t light = 0; light < count; ++light) {
            const LightAlone alone = renderLightAlone(renderer, scene, s, light, kWidth, kHeight);
            for (std::size_t i = 0; i < sum.size(); ++i) {
                if (!all.isGreyScene(i)) continue;
                reaching[i] += alone.reach[i];
                sum[i] += alone.shadowFactor[i];
            }
            // Every casting light of the set casts somewhere it reaches (a light whose map was lost would not).
            if (s.lights[light].castsShadows && s.lights[light].enabled)
                EXPECT_GT(alone.shadowed, 20) << "light " << light << " (" << lightTypeName(s.lights[light].type)
                                              << ") casts no visible shadow on its own; it reaches "
                                              << alone.reached << " pixels";
        }
        long compared = 0, off = 0;
        int worst = 0;
        for (std::size_t i = 0; i < sum.size(); ++i) {
            if (!all.isGreyScene(i) || reaching[i] < 0.5) continue;
            const int expected = int(std::lround(255.0 * sum[i] / std::round(reaching[i])));
            const int got = all.rgba[i * 4];
            ++compared;
            // 8-bit rounding of each light's frame, summed over at most four lights: within 3 levels.
            const int d = std::abs(got - expected);
            worst = std::max(worst, d);
            off += d > 3;
        }
        EXPECT_GT(compared, kWidth * kHeight / 4);
        EXPECT_EQ(off, 0) << "of " << compared << " pixels, the full frame's mean S differs from the lights' own "
                          << "(worst " << worst << " of 255)";
    }
}

}  // namespace
}  // namespace shadowlab::test
