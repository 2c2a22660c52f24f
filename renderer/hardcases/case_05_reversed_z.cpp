// HARD_CASES 5: reversed-Z. Near maps to 1 and far to 0, the comparison becomes GEQUAL, the depth clear 0, the bias
// sign flips and the "lit outside" border depth becomes 0; in GL it only gains precision with glClipControl(...,
// GL_ZERO_TO_ONE). Every other case runs again in the reversed convention (`lights.N.shadow.reversedZ`, set on every
// light of every Settings a case renders): each measurement's mask (S >= 0.5 per pixel) must equal the normal
// convention's apart from case 4's precision gains, every sub-check keeps its verdict, and the border policy (case
// 6) and the bias sign (a positive DepthBias still ends acne) are checked explicitly.
#include "hardcases/cases.h"

#include "hardcases/hard_case_runner.h"
#include "scene/builtin_scenes.h"

#include <algorithm>

namespace shadowlab::hardcases {

namespace {

// The share (percent) of pixels measured in both masks whose shadow state differs.
double maskDifference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    if (a.size() != b.size()) return 100.0;
    std::size_t both = 0, differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i] == 2 || b[i] == 2) continue;
        ++both;
        differ += a[i] != b[i];
    }
    return both ? 100.0 * double(differ) / double(both) : 0.0;
}

}  // namespace

void runReversedZ(CaseContext& context, CaseResult& result) {
    if (std::string missing = CaseContext::reversedZMissing(); !missing.empty()) {
        result.notRun("every other case in both conventions: masks", "equal (<= 0.1 % of pixels)", missing);
        result.notRun("border depth with reversed-Z (case 6's policy)", "lit outside", missing);
        result.notRun("bias sign: the default bias ends acne", "acne < 0.1 %", missing);
        return;
    }
    const bool record = context.recordMasks;
    const std::optional<bool> convention = context.reversedZ;
    const bool picturesOn = context.picturesOn;
    context.recordMasks = true;
    context.picturesOn = false;  // the pictures are the normal run's
    for (const HardCase& other : hardCaseList()) {
        if (other.number == 5 || other.number == 4) continue;  // case 4 has its own reversed-Z column
        const std::string prefix = std::to_string(other.number) + "/";
        const auto& asSet = context.masks["as set"];
        const bool haveNormal = std::any_of(asSet.begin(), asSet.end(),
                                            [&](const auto& m) { return m.first.starts_with(prefix); });
        CaseResult normal;
        if (!haveNormal) {  // --case 5 alone: run the case in the normal convention first
            context.reversedZ.reset();
            normal = runCase(other, context);
        }
        context.reversedZ = true;
        const CaseResult reversed = runCase(other, context);
        context.reversedZ = convention;
        double worst = 0.0;
        int measurements = 0;
        for (const auto& [label, mask] : context.masks["reversed-Z"]) {
            if (!label.starts_with(prefix)) continue;
            const auto match = context.masks["as set"].find(label);
            worst = std::max(worst, match == context.masks["as set"].end() ? 100.0 : maskDifference(match->second, mask));
            ++measurements;
        }
        // Rows whose verdict differs from the normal convention's (a row failing in both is that case's own failure).
        const std::vector<Verdict>& before = context.verdicts["as set"][other.number];
        int changedRows = 0;
        if (before.size() != reversed.rows.size())
            changedRows = int(std::max(before.size(), reversed.rows.size()));
        else
            for (std::size_t i = 0; i < before.size(); ++i) changedRows += before[i] != reversed.rows[i].verdict;
        const std::string figureText =
            !reversed.error.empty() ? "error: " + reversed.error
            : measurements == 0     ? "no mask (renders or flicker only), " + std::to_string(changedRows) + " verdicts changed"
                                    : percent(worst) + " of pixels, " + std::to_string(changedRows) + " verdicts changed";
        result.check("case " + std::to_string(other.number) + " reversed: worst mask difference over " +
                         std::to_string(measurements) + " measurements",
                     figureText, "<= 0.1 %, no verdict changed",
                     reversed.error.empty() && worst <= 0.1 && changedRows == 0);
        if (other.number == 6 && !reversed.rows.empty())
            result.check("border: case 6's policy reversed (" + reversed.rows.front().measured + ")",
                         reversed.rows.front().figure, reversed.rows.front().threshold,
                         reversed.rows.front().verdict == Verdict::Pass);
    }
    context.startCase(&result);
    context.recordMasks = record;
    context.picturesOn = picturesOn;

    // The bias sign: on textbook, no bias has acne in both conventions; DepthBias 2 / slope 2 ends it in both.
    const Scene textbook = *makeBuiltinScene("textbook");
    const int width = context.pick(320, 160), height = context.pick(180, 90);
    for (bool reversedZ : {false, true}) {
        context.reversedZ = reversedZ;
        Settings s;  // the default bias: DepthBias 2, slope 1, half a texel of normal offset, the receiver's plane
        const AccuracyReport biased = context.measure(textbook, s, width, height, reversedZ ? "bias-reversed" : "");
        s.lights[0].shadow.depthBias = 0.0f;
        s.lights[0].shadow.slopeScaledDepthBias = 0.0f;
        s.lights[0].shadow.normalOffset = 0.0f;
        s.lights[0].shadow.receiverPlaneBias = false;
        const AccuracyReport bare = context.measure(textbook, s, width, height);
        if (!biased.ok || !bare.ok) throw std::runtime_error(biased.ok ? bare.error : biased.error);
        result.check(std::string(reversedZ ? "reversed-Z" : "normal") + ": acne with the default bias (without any: " +
                         percent(bare.acnePercent) + ")",
                     percent(biased.acnePercent), "< 0.1 % (the bias points away from the light)",
                     biased.acnePercent < 0.1 && bare.acnePercent > biased.acnePercent);
    }
    context.reversedZ = convention;
}

}  // namespace shadowlab::hardcases
