// Issue 21, PCSS: the textbook shadow where the hard reference has it; a penumbra that widens with the light's size
// and is closer to the soft reference's than PCF 3x3's; contact hardening (narrow where the caster touches the
// receiver, wide far from it).
#include "gl_fixture.h"
#include "probe/pixel_probe.h"
#include "reference_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadowlab::test {
namespace {

class PcssAccuracy : public GlTest {};

constexpr int kWidth = 320, kHeight = 180;

Settings pcss(Settings s, float sizeDeg) {
    s.filter.kind = FilterKind::Pcss;
    s.lights[0].size = sizeDeg;
    s.reference.softRays = 128;
    return s;
}

AccuracyReport measured(AccuracyMeter& meter, const Scene& scene, const Settings& s, const std::string& name) {
    const Camera camera = cameraFor(s.camera, scene, double(kWidth) / kHeight);
    const AccuracyReport r = meter.measure(scene, s, camera, kWidth, kHeight);
    EXPECT_TRUE(r.ok) << r.error;
    saveOverlay(r, name);
    std::printf("%-22s wrong %.3f %%, acne %.3f %%, leak %.3f %%", name.c_str(), r.wrongPercent, r.acnePercent,
                r.leakPercent);
    if (r.soft.measured)
        std::printf("; soft: mean |S-V| %.4f, penumbra %.4f (reference %.4f, error %+.4f) world, %zu profiles",
                    r.soft.meanError, r.soft.penumbra.techniqueWorld, r.soft.penumbra.referenceWorld,
                    r.soft.penumbra.errorWorld, r.soft.counts.profiles);
    std::printf("\n");
    return r;
}

TEST_F(PcssAccuracy, PutsTheTextbookShadowWhereTheHardReferenceHasIt) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    const Settings base = loadShippedPreset("default");
    const AccuracyReport pcf = measured(meter, scene, base, "pcss-textbook-pcf3");
    for (float size : {0.0f, 1.0f}) {
        SCOPED_TRACE(size);
        const AccuracyReport r = measured(meter, scene, pcss(base, size), "pcss-textbook-" + std::to_string(int(size)));
        EXPECT_GT(r.counts.shadowed, 250u);  // the hard reference's shadow at 320x180: 339 pixels
        // Against the hard reference (a point light): within 0.1 % of wrong pixels, as the other techniques; a
        // 1-degree sun's penumbra (half lit) is not wrong by more than that either.
        EXPECT_LT(r.wrongPercent, 0.1);
        EXPECT_LT(r.wrongPercent, pcf.wrongPercent + 0.05);
        EXPECT_LE(r.acnePercent, 0.1) << "acne";
        EXPECT_LE(r.leakPercent, 0.2) << "leak";
    }
}

TEST_F(PcssAccuracy, PenumbraWidensWithTheLightsSizeAndFollowsTheSoftReferenceBetterThanPcf3) {
    const Scene scene = loadBuiltin("textbook");
    AccuracyMeter meter;
    // Close over the floating box's detached shadow (its bottom 2.75 above the floor: a gap of 3.1 along the light),
    // where a screen pixel (0.018 world units) is finer than the penumbrae measured.
    const Settings base = topDownAt(loadShippedPreset("default"), 2.8f, -3.9f, 4.0f);
    double previous = 0.0;
    for (float size : {1.0f, 2.0f, 4.0f}) {
        SCOPED_TRACE(size);
        const AccuracyReport r = measured(meter, scene, pcss(base, size), "pcss-soft-" + std::to_string(int(size)));
        ASSERT_TRUE(r.soft.measured);
        EXPECT_GT(r.soft.counts.profiles, 10u);
        EXPECT_GT(r.soft.penumbra.techniqueWorld, previous * 1.3) << "PCSS's penumbra grows with lights.0.size";
        previous = r.soft.penumbra.techniqueWorld;
        // Within 10 % of the reference's width (llvmpipe: 1.04x / 1.01x / 1.01x at 1 / 2 / 4 degrees). PCSS's disk
        // (pcss_filter.cpp's pcssDisk) samples the light's disc by area; the Poisson disk it used before spanned the
        // square and made every width 1.33x (0.061 / 0.120 / 0.239 against 0.046 / 0.090 / 0.179).
        EXPECT_NEAR(r.soft.penumbra.techniqueWorld / r.soft.penumbra.referenceWorld, 1.0, 0.10);
        if (size == 2.0f) {
            // PCF 3x3 under the same 2-degree sun: its penumbra is the map's, not the light's.
            Settings p = base;
            p.lights[0].size = size;
            p.reference.softRays = 128;
            const AccuracyReport pcf = measured(meter, scene, p, "pcss-soft-pcf3-2");
            // llvmpipe: PCSS +0.001 (0.091 vs 0.090 world units), PCF 3x3 -0.049 (0.044); mean |S-V| 0.0014 vs 0.0057.
            EXPECT_LT(std::abs(r.soft.penumbra.errorWorld), std::abs(pcf.soft.penumbra.errorWorld));
            EXPECT_LT(r.soft.meanError, pcf.soft.meanError);
        }
    }
}

// A wall standing on the floor, lit across it by a 4-degree sun: its shadow's side edge runs from the wall's foot
// (contact: blocker and receiver meet) to its top's shadow. The penumbra there widens with the height of the wall
// point that casts it; PCSS's estimate and its S both show it, PCF 3x3's S does not.
TEST_F(PcssAccuracy, ContactHardeningThePenumbraNarrowsTowardTheContact) {
    const Scene scene = contactWallScene();
    const Settings s = atContactWallEdge(pcss(loadShippedPreset("default"), 4.0f));
    // Across the side edge (z from 2 to 4) at x = 0.7 (cast 0.5 above the floor) and at x = 3.7 (3.5 above).
    struct Band {
        double x, penumbra = 0.0;  // the probe's mean estimate (texels) at the edge
        double zLow = 1e9, zHigh = -1e9;  // where S is partial (0.05 .. 0.95)
        int estimates = 0;
    };
    const auto bands = [&](const Settings& settings, std::vector<Band> out) {
        Renderer renderer;
        PixelProbe probe;
        const Camera camera = cameraFor(settings.camera, scene, 320.0 / 180.0);
        EXPECT_EQ(probe.capture(renderer, scene, settings, camera, 320, 180), "");
        for (int y = 0; y < 180; ++y)
            for (int x = 0; x < 320; ++x) {
                const PixelProbeReport r = probe.at(x, y);
                if (!r.ok || std::abs(r.world.y) > 1e-3 || r.world.z < 2.0 || r.world.z > 4.0) continue;

                for (Band& b : out) {
                    if (std::abs(r.world.x - b.x) > 0.05) continue;
                    if (r.shadowGpu > 0.05 && r.shadowGpu < 0.95) {
                        b.zLow = std::min(b.zLow, r.world.z);
                        b.zHigh = std::max(b.zHigh, r.world.z);
                    }
                    if (r.search.blockers > 0 && std::abs(r.world.z - 3.0) < 0.05) {
                        b.penumbra += r.search.penumbraTexels;
                        ++b.estimates;
                    }
                }
            }
        return out;
    };
    const std::vector<Band> p = bands(s, {Band{0.7}, Band{3.7}});
    for (const Band& b : p)
        std::printf("PCSS at x = %.1f: penumbra estimate %.2f texels (%d pixels), S partial over z %.3f .. %.3f (%.3f)\n",
                    b.x, b.estimates ? b.penumbra / b.estimates : 0.0, b.estimates, b.zLow, b.zHigh, b.zHigh - b.zLow);
    ASSERT_GT(p[0].estimates, 0);
    ASSERT_GT(p[1].estimates, 0);
    // The estimate grows with the caster's height above the receiver (0.5 vs 3.5: 7x), and S's partial band too.
    EXPECT_GT(p[1].penumbra / p[1].estimates, 3.0 * p[0].penumbra / p[0].estimates);
    EXPECT_GT(p[1].zHigh - p[1].zLow, 2.5 * (p[0].zHigh - p[0].zLow));
    // PCF 3x3: the same narrow band at both ends (the map's texels, not the light).
    Settings pcf = s;
    pcf.filter.kind = FilterKind::Pcf;
    const std::vector<Band> q = bands(pcf, {Band{0.7}, Band{3.7}});
    for (const Band& b : q)
        std::printf("PCF 3x3 at x = %.1f: S partial over z %.3f .. %.3f (%.3f)\n", b.x, b.zLow, b.zHigh, b.zHigh - b.zLow);
    // (one or two screen pixels of 0.02 world units at both ends).
    EXPECT_LT(q[1].zHigh - q[1].zLow, 0.05);
    EXPECT_GT(p[1].zHigh - p[1].zLow, 4.0 * std::max(q[1].zHigh - q[1].zLow, 0.02));
}

}  // namespace
}  // namespace shadowlab::test
