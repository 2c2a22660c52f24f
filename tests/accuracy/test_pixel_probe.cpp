// Issue 13, "Why this pixel": the probe's CPU shadow factor, rebuilt from the stored texels its filter taps read,
// equals the GPU's S at the same pixel for every filter, address mode and light; where the taps disagree (acne at
// zero bias, shadow edges) it says which ones and why.
#include "gl_fixture.h"
#include "reference_fixture.h"
#include "probe/pixel_probe.h"
#include "probe/probe_description.h"
#include "shading/filter_taps.h"
#include "shading/filters/filter_technique.h"
#include "views/shadow_view.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab::test {
namespace {

class PixelProbeTest : public GlTest {};

struct Sweep {
    int surfaces = 0, lit = 0, shadowed = 0, partial = 0, mixedTaps = 0, uncertain = 0, disagree = 0;
    int otherFace = 0;  // a point light: pixels with a tap read from another cube face than the lookup's
    int searchUncertain = 0;  // PCSS: pixels whose blocker search had a test within float rounding
    std::string firstDisagreement;
};

// Captures `settings`' camera over a w x h view into `probe`, drawn by `renderer`: "" or why not.
std::string captureView(Renderer& renderer, PixelProbe& probe, const Scene& scene, const Settings& settings, int w,
                        int h) {
    return probe.capture(renderer, scene, settings, cameraFor(settings.camera, scene, double(w) / h), w, h);
}

// Probes every `step`-th pixel of a w x h view and checks CPU against GPU.
Sweep sweep(const Scene& scene, const Settings& settings, int w = 160, int h = 90, int step = 3) {
    Renderer renderer;
    PixelProbe probe;
    EXPECT_EQ(captureView(renderer, probe, scene, settings, w, h), "");
    Sweep s;
    for (int y = 0; y < h; y += step)
        for (int x = 0; x < w; x += step) {
            const PixelProbeReport r = probe.at(x, y);
            if (!r.ok) continue;
            ++s.surfaces;
            s.lit += r.shadowGpu == 1.0;
            s.shadowed += r.shadowGpu == 0.0;
            s.partial += r.shadowGpu > 0.0 && r.shadowGpu < 1.0;
            s.uncertain += r.shadowLow != r.shadowHigh;
            int litTaps = 0;
            bool otherFace = false;
            for (const ProbeTap& t : r.taps) {
                litTaps += t.value > 0.5;
                for (const ProbeTexel& texel : t.texels) otherFace = otherFace || (texel.face >= 0 && texel.face != r.face);
            }
            s.otherFace += otherFace;
            s.searchUncertain += r.search.uncertain;
            s.mixedTaps += litTaps > 0 && litTaps < int(r.taps.size());
            if (!r.agrees) {
                ++s.disagree;
                if (s.firstDisagreement.empty())
                    for (const std::string& line : describeProbe(r)) s.firstDisagreement += line + "\n";
            }
        }
    return s;
}

Settings withFilter(Settings s, FilterKind kind, int kernel = 3, int resolution = 2048) {
    s.filter.kind = kind;
    s.filter.kernel = kernel;
    s.lights[0].shadow.resolution = resolution;
    return s;
}

// Each moments technique at 16 and 32 bits from `base` (a 3-texel kernel; a map of `resolution16` or `resolution32`
// texels), with the name a failure is traced under ("VSM 16").
std::vector<std::pair<std::string, Settings>> momentsSettings(const Settings& base, int resolution16, int resolution32) {
    std::vector<std::pair<std::string, Settings>> all;
    for (FilterKind kind : {FilterKind::Vsm, FilterKind::Evsm2, FilterKind::Evsm4, FilterKind::Msm})
        for (int bits : {16, 32}) {
            Settings s = withFilter(base, kind, 3, bits == 16 ? resolution16 : resolution32);
            s.filter.momentBits = bits;
            all.emplace_back(std::string(filterTechnique(kind).name) + " " + std::to_string(bits), s);
        }
    return all;
}

TEST_F(PixelProbeTest, CpuShadowFactorEqualsTheGpusForEveryFilter) {
    const Scene scene = loadBuiltin("textbook");
    const Settings base = loadShippedPreset("default");
    for (const auto& [name, settings] :
         {std::pair{"point", withFilter(base, FilterKind::Point)}, std::pair{"hardware2x2", withFilter(base, FilterKind::Hardware2x2)},
          std::pair{"pcf3", withFilter(base, FilterKind::Pcf, 3)}, std::pair{"poisson", withFilter(base, FilterKind::Poisson)},
          // A coarse map: wide bilinear and PCF edges, so many pixels weigh texels of both sides.
          std::pair{"hardware2x2 256", withFilter(base, FilterKind::Hardware2x2, 3, 256)},
          std::pair{"pcf5 256", withFilter(base, FilterKind::Pcf, 5, 256)}}) {
        const Sweep s = sweep(scene, settings, 320, 180, 2);
        SCOPED_TRACE(name);
        EXPECT_GT(s.surfaces, 5000);
        EXPECT_EQ(s.disagree, 0) << s.firstDisagreement;
        // The view holds lit floor, shadow and (filtered) edges: the test covers all three.
        EXPECT_GT(s.lit, 100);
        EXPECT_GT(s.shadowed, 20);
        if (settings.filter.kind != FilterKind::Point) EXPECT_GE(s.partial, settings.lights[0].shadow.resolution < 2048 ? 20 : 1);
        EXPECT_LT(s.uncertain, s.surfaces / 20) << "rounding decides too many pixels";
    }
}

Settings withPcss(Settings s, float size, int resolution = 2048) {
    s = withFilter(s, FilterKind::Pcss, 3, resolution);
    s.lights[0].size = size;
    return s;
}

TEST_F(PixelProbeTest, CpuShadowFactorEqualsTheGpusForPcss) {
    // Issue 21: PCSS's S, rebuilt by its CPU mirror (shading/filters/pcss_filter.cpp: the blocker search over the
    // stored depths, the penumbra estimate, the per-pixel rotated disk, then the probe's bilinear comparisons),
    // equals the GPU's at every probed pixel: a 2-degree sun, a hard light (size 0: the minimal filter), a coarse
    // map, receiver-plane bias, and a spot light of radius 0.3.
    const Scene scene = loadBuiltin("textbook");
    const Settings base = loadShippedPreset("default");
    Settings plane = withPcss(base, 2.0f, 1024);
    plane.lights[0].shadow.receiverPlaneBias = true;
    Settings spot = withPcss(base, 0.3f);
    spot.lights[0].type = LightType::Spot;
    spot.lights[0].position = {3.0f, 9.0f, 2.0f};
    spot.lights[0].direction = {-0.3f, -1.0f, -0.2f};
    spot.lights[0].spotConeDeg = 70.0f;
    for (const auto& [name, settings] :
         {std::pair{"pcss 2 degrees", withPcss(base, 2.0f)}, std::pair{"pcss size 0", withPcss(base, 0.0f)},
          std::pair{"pcss 4 degrees 256", withPcss(base, 4.0f, 256)}, std::pair{"pcss receiver plane", plane},
          std::pair{"pcss spot", spot}}) {
        const Sweep s = sweep(scene, settings, 320, 180, 2);
        SCOPED_TRACE(name);
        EXPECT_GT(s.surfaces, 5000);
        EXPECT_EQ(s.disagree, 0) << s.firstDisagreement;
        EXPECT_GT(s.lit, 100);
        EXPECT_GT(s.shadowed, 20);
        EXPECT_GT(s.partial, 20);
        EXPECT_LT(s.uncertain, s.surfaces / 20) << "rounding decides too many pixels";
    }
    {
        // A point light (builtin:room, radius 0.1): the GPU moves the search and the filter across the lookup's cube
        // face by direction, and a tap that crosses the face's edge reads the next face (its nearest texel in the
        // search, its 2x2 texels through seamless filtering in the comparisons). The mirror follows each tap's
        // direction to its face's texels (shading/filters/cube_face_frame.h): CPU = GPU at every probed pixel, within
        // the probe's own bounds (comparisons within float rounding either way, bilinear weights to 8 bits). The old
        // mirror, reading the lookup's face as a 2D view, disagreed at 95 of 14400 (llvmpipe).
        const Sweep s = sweep(loadBuiltin("room"), withPcss(loadShippedPreset("room"), 0.1f, 1024), 320, 180, 2);
        SCOPED_TRACE("pcss point");
        EXPECT_GT(s.surfaces, 5000);
        EXPECT_EQ(s.disagree, 0) << s.firstDisagreement;
        EXPECT_GT(s.partial, 20);
        EXPECT_GT(s.otherFace, 20) << "the sweep covers taps that cross a cube edge";
        // Cube faces have no receiver plane and store perspective depth, which crowds near 1 far from the light: a
        // search tap on the receiver's own surface often reads a depth 2-6 float steps (3e-7) from the receiver's,
        // within its rounding (depthEps 4.8e-7), so the GPU's search may end either way (llvmpipe: 771 of 14400
        // pixels). The mirror lists those outcomes (each doubtful test either way) and the probe bounds S by their
        // S's: S's bounds still differ at 23 pixels only.
        EXPECT_GT(s.searchUncertain, 0) << "the sweep covers searches decided within rounding";
        EXPECT_LT(s.uncertain, s.surfaces / 100) << "rounding decides too many pixels";
        std::printf("pcss point light: %d of %d probed pixels disagree, %d partial, %d read another face, %d uncertain "
                    "(%d in the search)\n",
                    s.disagree, s.surfaces, s.partial, s.otherFace, s.uncertain, s.searchUncertain);
    }
    {
        // A wall's shadow under a 4-degree sun (the contact-hardening scene): the search's widest taps reach past
        // blockerSearchTexels (the disk's farthest tap times the radius), which the probe's read-back must cover.
        const Sweep s = sweep(contactWallScene(), atContactWallEdge(withPcss(base, 4.0f)), 320, 180, 1);
        SCOPED_TRACE("pcss wall 4 degrees");
        EXPECT_GT(s.surfaces, 50000);
        EXPECT_EQ(s.disagree, 0) << s.firstDisagreement;
        EXPECT_GT(s.partial, 1000);
        std::printf("pcss wall: %d of %d probed pixels disagree, %d partial\n", s.disagree, s.surfaces, s.partial);
    }
    // The probe explains the search: blockers found, their mean depth, the penumbra, the filter's radius and taps.
    Renderer renderer;
    PixelProbe probe;
    const Settings sun = withPcss(base, 2.0f);
    ASSERT_EQ(captureView(renderer, probe, scene, sun, 160, 90), "");
    bool explained = false;
    for (int y = 0; y < 90 && !explained; ++y)
        for (int x = 0; x < 160 && !explained; ++x) {
            const PixelProbeReport r = probe.at(x, y);
            if (!r.ok || !r.ownLookup || r.search.blockers == 0 || r.search.blockers == r.search.searchTaps) continue;
            std::string text;
            for (const std::string& line : describeProbe(r)) text += line + "\n";
            explained = text.find("nearer than the receiver") != std::string::npos &&
                        text.find("mean blocker depth") != std::string::npos &&
                        text.find("penumbra") != std::string::npos && text.find("16 taps") != std::string::npos;
            EXPECT_TRUE(explained) << text;
        }
    EXPECT_TRUE(explained);
}

TEST_F(PixelProbeTest, CpuShadowFactorEqualsTheGpusForEveryMomentsTechnique) {
    // Issue 21: a moments technique's S, rebuilt from the view's stored moments with the technique's CPU mirror
    // (shading/filters/), equals the GPU's at every probed pixel: both precisions, a blur, a coarse map.
    const Scene scene = loadBuiltin("textbook");
    const Settings base = loadShippedPreset("default");
    for (auto [name, s] : momentsSettings(base, 256, 1024)) {
        s.filter.blurWidth = 5.0f;
        const Sweep sw = sweep(scene, s, 320, 180, 2);
        SCOPED_TRACE(name);
        EXPECT_GT(sw.surfaces, 5000);
        EXPECT_EQ(sw.disagree, 0) << sw.firstDisagreement;
        EXPECT_GT(sw.lit, 100);
        EXPECT_GT(sw.partial, 20);  // filtered edges: the bound is evaluated away from 0 and 1
    }
    // A point light (builtin:room): the cube's moments are blurred across the faces' edges and the GPU reads them
    // seamlessly; the mirror reads a texel beyond the lookup's face's edge from the neighbouring face (a corner: the
    // mean of the three around it). Pixels near a cube edge agree too.
    for (const auto& [kind, bits] : {std::pair{FilterKind::Vsm, 32}, std::pair{FilterKind::Msm, 16}}) {
        Settings room = loadShippedPreset("room");
        room.filter.kind = kind;
        room.filter.momentBits = bits;
        room.filter.blurWidth = 5.0f;
        room.lights[0].shadow.resolution = 256;  // coarse: many pixels read across an edge
        const Sweep sw = sweep(loadBuiltin("room"), room, 320, 180, 2);
        SCOPED_TRACE(std::string("room ") + filterTechnique(kind).name + " " + std::to_string(bits));
        EXPECT_GT(sw.surfaces, 5000);
        EXPECT_EQ(sw.disagree, 0) << sw.firstDisagreement;
        EXPECT_GT(sw.otherFace, 20) << "the sweep covers reads across a cube edge";
        EXPECT_GT(sw.partial, 20);
        std::printf("room %s-%d: %d of %d probed pixels disagree, %d read another face\n", filterTechnique(kind).name,
                    bits, sw.disagree, sw.surfaces, sw.otherFace);
    }
    {
        // The picture's S across the cube's edges (neighbouring pixels whose lookups fall in different faces) against
        // S between neighbours of one face, in penumbrae: how much the seam shows (the figures of docs/techniques.md).
        Settings room = loadShippedPreset("room");
        room.filter.kind = FilterKind::Vsm;
        room.filter.blurWidth = 9.0f;
        room.lights[0].shadow.resolution = 128;
        const Scene roomScene = loadBuiltin("room");
        Renderer renderer;
        PixelProbe probe;
        const int w = 320, h = 180;
        ASSERT_EQ(probe.capture(renderer, roomScene, room, cameraFor(room.camera, roomScene, double(w) / h), w, h), "");
        std::vector<PixelProbeReport> at;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) at.push_back(probe.at(x, y));
        double across = 0.0, within = 0.0;
        int acrossPairs = 0, withinPairs = 0, acrossSteps = 0, withinSteps = 0;
        for (int y = 0; y + 1 < h; ++y)
            for (int x = 0; x + 1 < w; ++x)
                for (const PixelProbeReport* n : {&at[std::size_t(y * w + x + 1)], &at[std::size_t((y + 1) * w + x)]}) {
                    const PixelProbeReport& a = at[std::size_t(y * w + x)];
                    // One plane (not a wall's foot), points closer than 0.08 units (about a pixel on the floor; not the ceiling
                    // seen edge-on), in a penumbra (S varies there whatever the faces).
                    if (!a.ok || !n->ok || a.instance != n->instance ||
                        glm::dot(a.shadingNormal, n->shadingNormal) < 0.999 || glm::length(a.world - n->world) > 0.08)
                        continue;
                    if (std::max(a.shadowGpu, n->shadowGpu) < 0.02 || std::min(a.shadowGpu, n->shadowGpu) > 0.98) continue;
                    const double d = std::abs(a.shadowGpu - n->shadowGpu);
                    (a.face != n->face ? across : within) += d;
                    ++(a.face != n->face ? acrossPairs : withinPairs);
                    (a.face != n->face ? acrossSteps : withinSteps) += d > 0.1;
                }
        std::printf("room VSM 128^2 blur 9, %dx%d: |dS| between neighbouring penumbra pixels of one plane: across a cube edge "
                    "mean %.4f over %d pairs (%d over 0.1), within a face mean %.4f over %d pairs (%d over 0.1)\n", w, h,
                    across / std::max(acrossPairs, 1), acrossPairs, acrossSteps, within / std::max(withinPairs, 1),
                    withinPairs, withinSteps);
        EXPECT_GT(acrossPairs, 20);
    }
    // The probe explains the lookup: the moments and the technique's bound in words.
    Renderer renderer;
    PixelProbe probe;
    Settings vsm = withFilter(base, FilterKind::Vsm);
    ASSERT_EQ(captureView(renderer, probe, scene, vsm, 160, 90), "");
    bool explained = false;
    for (int y = 0; y < 90 && !explained; y += 3)
        for (int x = 0; x < 160 && !explained; x += 3) {
            const PixelProbeReport r = probe.at(x, y);
            if (!r.ok || !r.momentLookup) continue;
            std::string text;
            for (const std::string& line : describeProbe(r)) text += line + "\n";
            explained = text.find("Chebyshev bound") != std::string::npos && text.find("variance") != std::string::npos;
        }
    EXPECT_TRUE(explained);
}

TEST_F(PixelProbeTest, CpuShadowFactorEqualsTheGpusForEveryMomentsTechniqueWithMips) {
    // filter.momentMips: the GPU reads its moments trilinearly at the level of the pixel's footprint (dFdxFine /
    // dFdyFine of the position, carried into the map); the mirror takes the same derivatives from the surface's plane
    // at the quad neighbours' pixel centres (probe/pixel_footprint.h). Exact equality is impossible: the GPU's
    // derivative is a float difference of interpolated positions and its level and sub-texel weights have 8
    // fractional bits, so the mirror bounds S over its level +-1/64 and both roundings of each weight. Every pixel
    // parity of the quads is probed (step 3); the 1024^2 map is minified here (levels 1-3), so mips are read.
    const Scene scene = loadBuiltin("textbook");
    const Settings base = loadShippedPreset("default");
    for (auto [name, s] : momentsSettings(base, 1024, 1024)) {
        s.filter.momentMips = true;
        const Sweep sw = sweep(scene, s, 240, 135, 3);
        SCOPED_TRACE(name + " with mips");
        EXPECT_GT(sw.surfaces, 1000);
        EXPECT_EQ(sw.disagree, 0) << sw.firstDisagreement;
        EXPECT_GT(sw.partial, 20);
    }
    // A point light's cube faces (builtin:room), VSM with mips: the GPU filters a cube map seamlessly across face
    // edges at every level, and so does the mirror (a texel beyond the edge from the neighbouring face's level; a
    // 1024^2 face's level 8 is 4x4 texels, so walls seen edge-on read across an edge): reads inside a face (more than
    // 1.5 of the level's texels from its edges) and reads across an edge agree alike.
    {
        Settings room = loadShippedPreset("room");
        room.filter.kind = FilterKind::Vsm;
        room.filter.momentMips = true;
        const Scene roomScene = loadBuiltin("room");
        Renderer renderer;
        PixelProbe probe;
        ASSERT_EQ(captureView(renderer, probe, roomScene, room, 160, 90), "");
        int probed = 0, inside = 0, insideDisagree = 0, edgeDisagree = 0;
        std::string first;
        for (int y = 0; y < 90; y += 3)
            for (int x = 0; x < 160; x += 3) {
                const PixelProbeReport r = probe.at(x, y);
                if (!r.ok || !r.momentLookup) continue;
                ++probed;
                const double toEdge = std::min({r.lightTexture.x, 1.0 - r.lightTexture.x, r.lightTexture.y,
                                                1.0 - r.lightTexture.y}) * r.resolution;
                const bool inFace = toEdge > 1.5 * std::exp2(std::ceil(r.momentLevel));
                inside += inFace;
                if (r.agrees) continue;
                ++(inFace ? insideDisagree : edgeDisagree);
                if (inFace && first.empty())
                    for (const std::string& line : describeProbe(r)) first += line + "\n";
            }
        std::printf("room, VSM with mips: %d pixels probed, %d read inside their face (%d disagree), %d disagreements "
                    "where the read reaches a face edge\n", probed, inside, insideDisagree, edgeDisagree);
        EXPECT_GT(inside, 1000);
        EXPECT_EQ(insideDisagree, 0) << first;
        EXPECT_EQ(edgeDisagree, 0);
        EXPECT_GT(probed - inside, 50) << "the sweep covers reads across a face's edge";
    }
    // The probe names the level it read.
    Renderer renderer;
    PixelProbe probe;
    Settings vsm = withFilter(base, FilterKind::Vsm, 3, 1024);
    vsm.filter.momentMips = true;
    ASSERT_EQ(captureView(renderer, probe, scene, vsm, 160, 90), "");
    double deepest = -1.0;
    for (int y = 0; y < 90; y += 5)
        for (int x = 0; x < 160; x += 5) {
            const PixelProbeReport r = probe.at(x, y);
            if (r.ok && r.momentLookup) deepest = std::max(deepest, r.momentLevel);
        }
    EXPECT_GT(deepest, 1.0) << "a 1024^2 map seen at 160x90 is minified";
}

TEST_F(PixelProbeTest, ExplainsTheMoireOfAWideKernel) {
    // The default bias before issue 20 (slope 2, no receiver plane) with a 7x7 kernel: the far taps reach 3 texels
    // from the lookup, where the sloped floor's own depth (3 x m) passes its bias (0.8 texels + the normal offset):
    // most of the lit floor reads S < 1, and the probe shows those taps shadowed, in agreement with the GPU.
    const Scene scene = loadBuiltin("textbook");
    Settings old = loadShippedPreset("default");
    old.lights[0].shadow.slopeScaledDepthBias = 2.0f;
    old.lights[0].shadow.receiverPlaneBias = false;
    const Sweep s = sweep(scene, withFilter(old, FilterKind::Pcf, 7), 160, 90, 2);
    EXPECT_EQ(s.disagree, 0) << s.firstDisagreement;
    EXPECT_GT(s.mixedTaps, s.surfaces / 2);
    EXPECT_LT(s.lit, s.surfaces / 10);
    EXPECT_LT(s.uncertain, s.surfaces / 20);
}

TEST_F(PixelProbeTest, AcneAtZeroBiasIsExplainedTapByTap) {
    // Zero bias and no normal offset on a grazing light: each receiver meets its own surface in the map, so its taps
    // split into lit and shadowed ones — the stripes of acne. The probe must still agree with the GPU.
    const Scene scene = loadBuiltin("grazing");
    const Settings s = zeroBias(loadShippedPreset("default"));
    const Sweep acne = sweep(scene, s);
    EXPECT_EQ(acne.disagree, 0) << acne.firstDisagreement;
    EXPECT_GT(acne.mixedTaps, acne.surfaces / 10) << "zero bias should split the taps of many receivers";
    EXPECT_GT(acne.partial, acne.surfaces / 10);
    // The shipped bias removes most of that.
    const Sweep biased = sweep(scene, loadShippedPreset("default"));
    EXPECT_EQ(biased.disagree, 0) << biased.firstDisagreement;
    EXPECT_LT(biased.mixedTaps, acne.mixedTaps / 3);
}

TEST_F(PixelProbeTest, SpotLightWrapAndBorderAgreeToo) {
    const Scene scene = loadBuiltin("textbook");
    Settings spot = loadShippedPreset("default");
    spot.lights[0].type = LightType::Spot;
    spot.lights[0].position = {3.0f, 9.0f, 2.0f};
    spot.lights[0].direction = {-0.3f, -1.0f, -0.2f};
    spot.lights[0].spotConeDeg = 70.0f;
    const Sweep s = sweep(scene, spot);
    EXPECT_EQ(s.disagree, 0) << s.firstDisagreement;
    EXPECT_GT(s.shadowed, 20);
    Settings wrap = loadShippedPreset("default");
    wrap.lights[0].projection.autoFit = false;
    wrap.lights[0].projection.orthoSize = 8.0f;  // the view reaches outside the light's volume
    wrap.lights[0].projection.nearPlane = 0.1f;
    wrap.lights[0].projection.farPlane = 60.0f;
    for (AddressMode mode : {AddressMode::Wrap, AddressMode::ClampToEdge, AddressMode::ClampToBorder}) {
        wrap.sampler.addressMode = mode;
        const Sweep w = sweep(scene, withFilter(wrap, FilterKind::Hardware2x2));
        EXPECT_EQ(w.disagree, 0) << int(mode) << "\n" << w.firstDisagreement;
    }
}

TEST_F(PixelProbeTest, ReportsTheBiasTermsAndTapsOfOneFloorPixel) {
    const Scene scene = loadBuiltin("textbook");
    Settings s = topDownShadowView(loadShippedPreset("default"));
    s.lights[0].direction = {0.0f, -1.0f, 0.0f};
    s.lights[0].shadow.depthBias = 4.0f;
    s.lights[0].shadow.slopeScaledDepthBias = 3.0f;
    s.lights[0].shadow.depthBiasClamp = 0.01f;
    s.lights[0].shadow.normalOffset = 1.5f;
    s.filter = {FilterKind::Pcf, 5, 2.0f};
    Renderer renderer;
    PixelProbe probe;
    const int w = 200, h = 200;
    ASSERT_EQ(captureView(renderer, probe, scene, s, w, h), "");
    // The first lit floor pixel from the top left: away from every caster.
    PixelProbeReport r;
    for (int y = 0; y < h && !r.ok; y += 5)
        for (int x = 0; x < w && !r.ok; x += 5) {
            r = probe.at(x, y);
            if (r.ok && (std::abs(r.world.y) > 1e-6 || r.shadowGpu != 1.0)) r.ok = false;
        }
    ASSERT_TRUE(r.ok) << "no lit floor pixel";
    EXPECT_NEAR(r.world.y, 0.0, 1e-9);  // the floor, rebuilt in double
    EXPECT_EQ(r.taps.size(), 25u);
    EXPECT_EQ(filterTaps(s.filter).size(), 25u);
    EXPECT_DOUBLE_EQ(r.taps.front().offsetTexels.x, -2.0);
    EXPECT_DOUBLE_EQ(r.shadowCpu, 1.0);
    EXPECT_TRUE(r.agrees);
    // A floor facing a straight-down light has no depth slope: the slope term is 0, the constant is 4 r, the clamp
    // does not bite, and the normal offset is 1.5 texels of the map's world size, straight up.
    const double texel = probe.stats().light.texelWorldSize;
    EXPECT_NEAR(r.bias.depthSlope, 0.0, 1e-12);
    EXPECT_NEAR(r.bias.constant.depth, 4.0 * depthStepAt(DepthFormat::D32F, r.receiverDepth), 1e-12);
    EXPECT_NEAR(r.bias.total.depth, r.bias.constant.depth, 1e-12);
    EXPECT_NEAR(r.bias.clamp.depth, 0.01, 1e-9);
    EXPECT_NEAR(r.bias.normalOffsetWorld, 1.5 * texel, 1e-6 * texel);
    EXPECT_NEAR(r.lookupWorld.y - r.world.y, 1.5 * texel, 1e-6 * texel);
    // The stored depth of the floor's own texel is the floor's depth plus its bias (every tap reads the floor).
    for (const ProbeTap& t : r.taps)
        for (const ProbeTexel& x : t.texels) {
            EXPECT_FALSE(x.border);
            EXPECT_NEAR(x.stored, r.receiverDepth + r.bias.total.depth + 1.5 * texel / (probe.stats().light.farPlane - probe.stats().light.nearPlane), 1e-6);
        }
    // Outside the view and on the background: refused with the reason.
    EXPECT_FALSE(probe.at(w, 0).ok);
    EXPECT_NE(probe.at(0, 0).error.find("background"), std::string::npos);
    EXPECT_NE(probe.at(-1, 5).error.find("outside the 200x200 view"), std::string::npos);
}

TEST_F(PixelProbeTest, CopiesTheMeasurementsVerdictAndCause) {
    const Scene scene = loadBuiltin("grazing");
    Settings s = zeroBias(loadShippedPreset("default"));
    s.lights[0].shadow.receiverPlaneBias = false;  // every bias term off: the floor meets itself in the map
    const int w = 160, h = 90;
    const Camera camera = cameraFor(s.camera, scene, double(w) / h);
    AccuracyMeter meter;
    const AccuracyReport measured = meter.measure(scene, s, camera, w, h);
    ASSERT_TRUE(measured.ok) << measured.error;
    Renderer renderer;
    PixelProbe probe;
    ASSERT_EQ(probe.capture(renderer, scene, s, camera, w, h), "");
    int acne = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const PixelProbeReport r = probe.at(x, y, &measured);
            if (!r.ok || !r.measured) continue;
            EXPECT_NEAR(r.measuredShadow, r.shadowGpu, 1e-6);  // the same frame
            if (r.cause == MismatchCause::SelfShadowing) {
                ++acne;
                EXPECT_EQ(r.exact, PixelClass::Lit);
                EXPECT_LT(r.shadowCpu, 1.0);
            }
        }
    EXPECT_GT(acne, 50) << "zero bias on grazing: self-shadowing pixels named by the probe";
}

// Issue 20: a cascaded light. In a blend band the GPU mixes two cascades; the probe looks the surface up in both, at
// the selection's weight, and its mixed S equals the GPU's (compared with the holding cascade's S alone, pixels
// whose two cascades differ disagree). --view: another cascade's lookup, in that cascade's texels, not compared.
Settings cascadedTextbook() {
    Settings s = loadShippedPreset("default");
    LightSettings& sun = s.lights[0];
    sun.projection.fit = ProjectionFit::Cascades;
    sun.projection.cascadeCount = 3;
    sun.projection.shadowDistance = 30.0f;
    sun.projection.splitLambda = 0.6f;
    sun.projection.blendBand = 0.4f;
    sun.shadow.resolution = 256;  // coarse: the cascades' S differ along the shadow edges inside the bands
    s.camera.autoFrame = false;
    s.camera.position = {-4.0, 1.2, 9.0};
    s.camera.target = {1.0, 0.3, -3.0};
    return s;
}

TEST_F(PixelProbeTest, InACascadesBlendBandItMixesBothCascadesAsTheGpuDoes) {
    const Scene scene = loadBuiltin("textbook");
    const Settings s = cascadedTextbook();
    const int w = 240, h = 135;
    Renderer renderer;
    PixelProbe probe;
    ASSERT_EQ(captureView(renderer, probe, scene, s, w, h), "");
    ASSERT_EQ(probe.views().size(), 3u);
    int blended = 0, differing = 0, disagree = 0;
    std::string first;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const PixelProbeReport r = probe.at(x, y);
            if (!r.ok) continue;
            if (!r.agrees && ++disagree == 1)
                for (const std::string& line : describeProbe(r)) first += line + "\n";
            if (r.blend.empty()) continue;
            ++blended;
            const PixelProbeReport& next = r.blend.front();
            EXPECT_EQ(next.cascade, "cascade:" + std::to_string(std::stoi(r.cascade.substr(8)) + 1));
            EXPECT_GT(r.blendWeight, 0.0);
            EXPECT_LE(r.blendWeight, 1.0);
            EXPECT_NEAR(r.shadowCpu, (1.0 - r.blendWeight) * r.shadowView + r.blendWeight * next.shadowCpu, 1e-12);
            // The partner's bias is in its own (coarser) texels: the same normal offset setting, more world units.
            EXPECT_GT(next.bias.normalOffsetWorld, r.bias.normalOffsetWorld);
            // Where the mix matters: the two cascades' S differ by more than the GPU's tolerance, weighed by both.
            if (std::abs(next.shadowCpu - r.shadowView) * std::min(r.blendWeight, 1.0 - r.blendWeight) > 0.01)
                ++differing;
        }
    EXPECT_GT(blended, 500) << "the view holds blend bands";
    EXPECT_GT(differing, 5) << "pixels where the mix matters (the two cascades' S differ)";
    RecordProperty("blended", blended);
    RecordProperty("differing", differing);
    EXPECT_EQ(disagree, 0) << first;
}

TEST_F(PixelProbeTest, ViewChoosesACascadeAndSaysTheGpuDoesNotReadItThere) {
    const Scene scene = loadBuiltin("textbook");
    Settings s = cascadedTextbook();
    s.lights[0].projection.blendBand = 0.0f;
    const int w = 160, h = 90;
    Renderer renderer;
    PixelProbe probe;
    ASSERT_EQ(captureView(renderer, probe, scene, s, w, h), "");
    std::string error;
    const std::optional<std::size_t> two = findView(probe.views(), "cascade:2", error);
    ASSERT_TRUE(two) << error;
    EXPECT_FALSE(findView(probe.views(), "cascade:3", error));
    EXPECT_NE(error.find("light 0 has no such view: it has 3 views (allowed: cascade:0, cascade:1, cascade:2)"),
              std::string::npos) << error;
    int checked = 0;
    for (int y = h - 1; y >= 0 && checked < 20; y -= 2)
        for (int x = 0; x < w && checked < 20; x += 7) {
            const PixelProbeReport own = probe.at(x, y);
            if (!own.ok || own.cascade != "cascade:0") continue;
            const PixelProbeReport r = probe.at(x, y, nullptr, two);
            ASSERT_TRUE(r.ok) << r.error;
            EXPECT_EQ(r.cascade, "cascade:2");
            EXPECT_TRUE(r.viewChosen);
            EXPECT_FALSE(r.compared);
            EXPECT_NE(r.blendNote.find("the GPU reads cascade:0 here"), std::string::npos) << r.blendNote;
            // The same setting in cascade 2's texels: its world size scales with the texel.
            const double ratio = probe.views()[2].space.texelWorldSize / probe.views()[0].space.texelWorldSize;
            EXPECT_GT(ratio, 1.5);
            EXPECT_NEAR(r.bias.normalOffsetWorld / own.bias.normalOffsetWorld, ratio, 1e-6 * ratio);
            // The cascade the GPU reads, asked for by name, is compared as without --view.
            const PixelProbeReport zero = probe.at(x, y, nullptr, std::size_t(0));
            EXPECT_TRUE(zero.compared && zero.agrees);
            EXPECT_EQ(zero.shadowCpu, own.shadowCpu);
            ++checked;
        }
    EXPECT_EQ(checked, 20);
}

}  // namespace
}  // namespace shadowlab::test
