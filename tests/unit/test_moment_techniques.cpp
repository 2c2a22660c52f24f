// Issue 21: the moments techniques as units (VSM, EVSM2/4, MSM): their CPU mirrors, the clamps of their storage,
// the blur's weights, and that a technique's keys are key-table entries shown only while it is chosen.
#include "settings/settings_fields.h"
#include "shading/filters/filter_technique.h"
#include "shading/filters/moments_mirror.h"

#include <gtest/gtest.h>

#include <cmath>

namespace shadowlab {
namespace {

FilterSettings filterOf(FilterKind kind, int bits = 32) {
    FilterSettings f;
    f.kind = kind;
    f.momentBits = bits;
    return f;
}

TEST(MomentTechniques, VsmBleedsTheDocumentsTwentyPercentAndTheReductionLowersIt) {
    // HARD_CASES.md case 21: casters at depths 0.2 and 0.6, each half the filter window, over a receiver at 0.8.
    FilterSettings f = filterOf(FilterKind::Vsm);
    f.minVariance = 0.0f;
    f.bleedReduction = 0.0f;
    const MomentTechnique& vsm = *vsmFilter().moments;
    const glm::vec4 u = vsm.uniforms(f);
    const glm::vec4 window = 0.5f * vsm.encode(0.2f, u) + 0.5f * vsm.encode(0.6f, u);
    EXPECT_NEAR(window.x, 0.4f, 1e-6f);  // the mean
    EXPECT_NEAR(window.y, 0.2f, 1e-6f);  // E[x^2]; variance 0.04
    EXPECT_NEAR(vsm.shadow(window, 0.8f, u), 0.2f, 1e-5f) << "fully shadowed, yet 20 % lit";
    f.bleedReduction = 0.2f;
    EXPECT_NEAR(vsm.shadow(window, 0.8f, vsm.uniforms(f)), 0.0f, 1e-5f);
    f.bleedReduction = 0.1f;
    const float reduced = vsm.shadow(window, 0.8f, vsm.uniforms(f));
    EXPECT_GT(reduced, 0.0f);
    EXPECT_LT(reduced, 0.2f);
    // A receiver in front of the mean is lit.
    EXPECT_EQ(vsm.shadow(window, 0.3f, u), 1.0f);
}

TEST(MomentTechniques, EvsmExponentsAreClampedToWhatTheStorageHolds) {
    for (FilterKind kind : {FilterKind::Evsm2, FilterKind::Evsm4}) {
        const MomentTechnique& m = *filterTechnique(kind).moments;
        FilterSettings f = filterOf(kind, 16);
        f.positiveExponent = 40.0f;
        f.negativeExponent = 10.0f;
        const std::vector<std::string> clamps = m.clamps(f);
        ASSERT_FALSE(clamps.empty());
        EXPECT_NE(clamps[0].find("filter.positiveExponent 40"), std::string::npos) << clamps[0];
        EXPECT_NE(clamps[0].find("5.54 is used"), std::string::npos) << clamps[0];
        EXPECT_EQ(clamps.size(), kind == FilterKind::Evsm4 ? 2u : 1u);
        EXPECT_FLOAT_EQ(m.uniforms(f).x, 5.54f);
        // At the largest exponent each storage allows, the moments of the farthest and nearest depth are finite
        // and the second moment fits the format (fp16: 65504).
        for (int bits : {16, 32}) {
            FilterSettings top = filterOf(kind, bits);
            top.positiveExponent = top.negativeExponent = maxWarpExponent(bits);
            EXPECT_TRUE(m.clamps(top).empty());
            for (float z : {0.0f, 1.0f}) {
                const glm::vec4 stored = storedMoments(m.encode(z, m.uniforms(top)), m, bits);
                for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(stored[c])) << bits << " bits, z " << z;
            }
        }
        // Above it fp16 overflows: the clamp is what keeps the map finite.
        const glm::vec4 unclamped(6.0f, 6.0f, 0.0f, 0.0f);
        EXPECT_TRUE(std::isinf(storedMoments(m.encode(1.0f, unclamped), m, 16).y));
    }
    FilterSettings fine = filterOf(FilterKind::Evsm4, 32);
    fine.positiveExponent = 42.0f;
    EXPECT_TRUE(evsm4Filter().moments->clamps(fine).empty());
}

TEST(MomentTechniques, MsmQuantizationIsInvertedByItsDecoding) {
    const MomentTechnique& msm = *msmFilter().moments;
    FilterSettings f = filterOf(FilterKind::Msm, 16);
    f.momentBias = 0.0f;
    f.bleedReduction = 0.0f;
    const glm::vec4 u = msm.uniforms(f);
    // Quantized moments of a depth are in [0, 1] (unorm storage) and the lookup of the receiver at that depth's
    // far side is dark, near side lit.
    for (float z : {0.05f, 0.3f, 0.5f, 0.9f}) {
        const glm::vec4 q = msm.encode(z, u);
        for (int c = 0; c < 4; ++c) {
            EXPECT_GE(q[c], -1e-4f) << z;
            EXPECT_LE(q[c], 1.0f + 1e-4f) << z;
        }
        const glm::vec4 mixed = 0.5f * msm.encode(z, u) + 0.5f * msm.encode(std::min(z + 0.05f, 1.0f), u);
        EXPECT_LT(msm.shadow(mixed, std::min(z + 0.2f, 1.0f), u), 0.05f) << z;
        EXPECT_GT(msm.shadow(mixed, z - 0.02f, u), 0.95f) << z;
    }
}

TEST(MomentTechniques, BlurWeightsAreABoxWithFractionalEnds) {
    EXPECT_EQ(blurWeights(1.0), std::vector<float>{1.0f});
    const std::vector<float> three = blurWeights(3.0);
    ASSERT_EQ(three.size(), 3u);
    for (float w : three) EXPECT_NEAR(w, 1.0f / 3.0f, 1e-7f);
    const std::vector<float> two = blurWeights(2.0);
    ASSERT_EQ(two.size(), 3u);
    EXPECT_NEAR(two[0], 0.25f, 1e-7f);
    EXPECT_NEAR(two[1], 0.5f, 1e-7f);
    FilterSettings world;
    world.blurUnit = BlurUnit::World;
    world.blurWidth = 0.5f;
    EXPECT_NEAR(blurTexels(world, 0.1), 5.0, 1e-9);  // half a unit in every cascade: 5 texels of 0.1
    EXPECT_NEAR(blurTexels(world, 0.05), 10.0, 1e-9);
    bool clamped = false;
    EXPECT_EQ(blurTexels(world, 0.001, &clamped), kMaxBlurTexels);
    EXPECT_TRUE(clamped);
}

TEST(MomentTechniques, FilterKindNamesAndKeysComeFromTheTechniqueTable) {
    const SettingsField& kind = *findSettingsField("filter.kind");
    ASSERT_EQ(kind.choices.size(), filterTechniques().size());
    for (std::size_t i = 0; i < filterTechniques().size(); ++i) {
        const FilterTechnique& t = *filterTechniques()[i];
        EXPECT_EQ(kind.choices[i], t.name);
        for (const char* key : t.keys) EXPECT_NE(findSettingsField(key), nullptr) << t.name << ": " << key;
        EXPECT_EQ(t.moments != nullptr, i >= 4 && i < 8) << t.name;  // pcss (8): a lookup of its own
        EXPECT_EQ(t.ownLookup != nullptr, i == 8) << t.name;
    }
}

}  // namespace
}  // namespace shadowlab
