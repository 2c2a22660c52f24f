#pragma once
// The tuner. Its bias search suggests DepthBias, SlopeScaledDepthBias, normal offset, with a PCF / Poisson filter
// whether to use receiver-plane depth bias (each way is searched; the plane usually needs far less slope bias) and,
// when culled casters cause wrong pixels, the shadow pass's cull mode: among the candidates whose acne (metrics
// version 2) is at most maxAcnePercent, the fewest wrong pixels beyond k, then the smallest edge error, then the
// smallest bias. Its trade-off search varies the keys the filter technique declares (FilterTechnique::tradeOff: VSM's
// minimum variance and bleeding reduction, EVSM's exponents, MSM's moment bias...), one key at a time over its
// declared candidates with the others at the best so far (at most two rounds), and keeps among the candidates with
// acne <= maxAcnePercent the least error: a light with a size, the soft metrics against the soft reference (mean
// |S-V|, then bleeding, then over-darkening); a hard light, version 2's (mean |S-V|, then leak = lit umbra pixels,
// then acne). It never suggests a setting above the limit: when none reaches it, it says so and names the cause that
// stops it. Candidates are measured with an AccuracyMeter (each costs one tool frame: the reference is cached).
// Other settings are kept as given.
#include "accuracy/accuracy_meter.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

struct TuneStep {
    int index = 0;                   // 1-based candidate number
    std::string phase;               // what the search was doing, e.g. "start", "zero bias", "grow slope", "bisect"
    float depthBias = 0.0f;          // D3D DepthBias (format depth steps)
    float slopeScaledDepthBias = 0.0f;
    float normalOffset = 0.0f;       // texels
    CullMode cullMode = CullMode::None;
    bool receiverPlaneBias = false;
    double biasTexels = 0.0;         // the bias's size in texels (constant + slope + normal offset), for the tie-break
    double acnePercent = 0.0;
    double leakPercent = 0.0;
    double wrongPercent = 0.0;
    std::size_t wrongBeyondK = 0;
    double meanError = 0.0;
    double edgeErrorTexels = 0.0;
    // A cascaded light: each cascade's acne % over the pixels it holds (nearest first), and the worst of those that
    // hold at least kTuneCascadeMinPixels measured pixels (-1: none); the limit holds only when it holds in each.
    std::vector<double> cascadeAcnePercent;
    int worstCascade = -1;
    bool withinLimit = false;        // acnePercent <= maxAcnePercent (a cascaded light: in every judged cascade too)
    bool bestSoFar = false;          // this candidate became the best so far (of its search: bias or trade-off)
    // The trade-off search's candidates: the values of TuneResult::tradeOffKeys (empty for a bias candidate).
    bool tradeOffStep = false;
    std::vector<double> tradeOff;
    // A light with a size: the soft numbers against the soft reference (soft_metrics.h).
    bool soft = false;
    double softMeanError = 0.0;
    double softWrongPercent = 0.0;
    double bleedingPercent = 0.0;
    double overDarkeningPercent = 0.0;
    double penumbraErrorWorld = 0.0;
    // What the candidate cost: the whole measurement (the first also builds the reference) and its tool frame.
    double costMs = 0.0;
    double toolFrameMs = 0.0;
};

// What the trade-off search compares (a light with a size: the soft numbers; else version 2's): the error, the
// bleeding (light in the true umbra) and the darkening of lit ground.
double tradeOffError(const TuneStep& s);
double tradeOffBleeding(const TuneStep& s);
double tradeOffDarkening(const TuneStep& s);
// Errors within this share of each other are a tie, decided by bleeding, then darkening.
inline constexpr double kTradeOffTie = 0.01;
// Is a a better trade-off than b? Within the acne limit first; among those the least error (ties: kTradeOffTie), then
// the least bleeding, then the least darkening; outside the limit, the least acne.
bool betterTradeOff(const TuneStep& a, const TuneStep& b);

// What `tune` searches: the depth bias, the technique's trade-off keys, or both (the bias first, then the trade-off
// from the bias found). Auto: the trade-off when the technique declares one, else the bias.
enum class TuneSearch { Auto, Bias, TradeOff, Both };
// "auto", "bias", "technique", "both" (the CLI's --search values); parseTuneSearch: nullopt for another name.
const char* tuneSearchName(TuneSearch search);
std::optional<TuneSearch> parseTuneSearch(const std::string& name);

struct TuneScope {
    TuneSearch search = TuneSearch::Bias;
    // false: only the technique's per-light keys ("lights.#.") are searched, its global ones (filter.*) stay as given
    // (a later light of several: the global keys were tuned on the first).
    bool globalKeys = true;
};

// What a search of `scope` runs for settings whose filter is `kind`: Auto resolved (the trade-off when the technique
// declares keys within the scope, else the bias); Bias, TradeOff or Both as asked. The CLI and the editor say it.
TuneSearch resolveTuneSearch(const TuneScope& scope, FilterKind kind);
// The trade-off keys a search of `scope` varies for `kind`, as declared ("filter.minVariance", "lights.#.size").
std::vector<std::string> tradeOffKeysOf(const TuneScope& scope, FilterKind kind);
// A trade-off key the tuner saw on its one light ("lights.0.size") as light `index`'s key of the whole preset
// ("lights.2.size"); a global key ("filter.minVariance") as it is.
std::string keyOfLight(const std::string& key, std::size_t index);

// A cascade holding fewer measured pixels than this is not judged on its own (one acne pixel of 20 is 5 %); its
// pixels still count in the light's overall acne.
inline constexpr std::size_t kTuneCascadeMinPixels = 200;

// Is a a better suggestion than b? Within the acne limit first; among those the fewest wrong pixels beyond k, then
// the smallest edge error, then the smallest bias; outside the limit, the least acne (limitingAcne).
bool betterCandidate(const TuneStep& a, const TuneStep& b);
// The acne that decides a candidate outside the limit: its overall acne, or its worst judged cascade's if higher.
double limitingAcne(const TuneStep& s);

// The preset spelling of a cull mode ("back", "front", "none"), from the settings' key table.
std::string cullModeName(CullMode mode);

struct TuneResult {
    bool ok = false;
    bool cancelled = false;
    std::string error;               // when !ok
    bool reachedLimit = false;       // false: no candidate reached acne <= maxAcnePercent
    Settings best;                   // reached: start with the best bias (cull mode, receiver plane) found; else start
    Settings closest;                // the candidate with the least acne (== best when reached)
    MismatchCause blockingCause = MismatchCause::None;  // not reached: the cause of most of closest's acne
    // Not reached on a cascaded light: the cascade whose acne stays above the limit at the closest candidate (the
    // worst judged one), its texel, the measured pixels it holds and its acne there; -1 when no judged cascade is
    // above it or the light has no cascades. blockingCascadeLeastAcne: the least acne it reached with any candidate.
    int blockingCascade = -1;
    double blockingCascadeTexel = 0.0;
    std::size_t blockingCascadePixels = 0;
    double blockingCascadeAcne = 0.0;
    double blockingCascadeLeastAcne = 0.0;
    std::vector<TuneStep> path;      // every candidate measured, in order
    AccuracyReport report;           // the measurement of `closest`
    double seconds = 0.0;            // wall time of the search
    AccuracyCost referenceCost;      // what the first measurement (which built the reference) cost
    // When the search ran both ways (PCF / Poisson): the best candidate with receiver-plane bias and without it, by
    // the same criterion; index 0 = off, 1 = on (nullopt: that way was not searched).
    std::optional<TuneStep> bestByPlane[2];
    // The trade-off search (when it ran): the keys it varied ("filter.minVariance", "lights.0.size"...), in the order
    // of TuneStep::tradeOff, and each value of the start it lowered to what the settings can use (EVSM's exponents
    // at 16 bits), in words.
    bool tradeOffSearched = false;
    std::vector<std::string> tradeOffKeys;
    std::vector<std::string> startClamps;
};

// Why the tuner kept or dropped receiver-plane bias, in one sentence ("" when it searched only one way).
std::string receiverPlaneChoice(const TuneResult& result);

TuneResult tuneBias(AccuracyMeter& meter, const Scene& scene, const Settings& start, const Camera& camera, int width,
                    int height, double maxAcnePercent = 0.1, AccuracyProgress* progress = nullptr,
                    std::function<void(const TuneStep&)> onStep = {}, TuneScope scope = {});

}  // namespace shadowlab
