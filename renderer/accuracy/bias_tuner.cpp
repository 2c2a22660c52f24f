#include "light/scene_lights.h"
#include "accuracy/bias_tuner.h"

#include "accuracy/light_isolation.h"

#include "light/depth_bias.h"
#include "light/light_space.h"
#include "settings/settings_fields.h"
#include "shading/filters/filter_technique.h"
#include "views/shadow_view.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>

namespace shadowlab {

namespace {

// A bias setting in texel terms: the constant part in shadow-map texels, slope as is, normal offset in texels.
struct Candidate {
    double constantTexels = 0.0;
    double slope = 0.0;
    double normal = 0.0;
    double magnitude() const { return constantTexels + slope + normal; }
};

// Settings' limits (settings_fields.cpp): DepthBias <= 1e6 units, slope <= 100, normal offset <= 16 texels.
constexpr double kMaxDepthBiasUnits = 1e6;
constexpr double kMaxSlope = 100.0;
constexpr double kMaxNormalTexels = 16.0;
constexpr int kBisections = 3;
constexpr int kMaxSteps = 2 + 4 * (10 + kBisections);  // for the progress bar: start, zero bias, 4 families
                                                       // (cull mode candidates extend it; the bar then rescales)
constexpr float kFirstShare = 0.3f;                    // of the progress bar: the first candidate's reference

// What the search varies besides the bias amounts: the cull mode and receiver-plane bias.
struct Variant {
    CullMode cull = CullMode::None;
    bool plane = false;
    bool operator==(const Variant&) const = default;
};

// One search direction: the bias grows with t along it.
struct Family {
    const char* name;
    std::function<Candidate(double t)> at;
    double tMax;
};

}  // namespace

std::string cullModeName(CullMode mode) {
    Settings s;
    s.lights[0].shadow.cullMode = mode;
    return findSettingsField("shadow.cullMode")->get(s).get<std::string>();
}

double limitingAcne(const TuneStep& s) {
    return s.worstCascade < 0 ? s.acnePercent
                              : std::max(s.acnePercent, s.cascadeAcnePercent[std::size_t(s.worstCascade)]);
}

bool betterCandidate(const TuneStep& a, const TuneStep& b) {
    if (a.withinLimit != b.withinLimit) return a.withinLimit;
    if (!a.withinLimit) {  // the least acne where it is worst (a cascaded light: its worst judged cascade)
        if (limitingAcne(a) != limitingAcne(b)) return limitingAcne(a) < limitingAcne(b);
        if (a.wrongBeyondK != b.wrongBeyondK) return a.wrongBeyondK < b.wrongBeyondK;
        return a.biasTexels < b.biasTexels;
    }
    if (a.wrongBeyondK != b.wrongBeyondK) return a.wrongBeyondK < b.wrongBeyondK;
    if (a.edgeErrorTexels != b.edgeErrorTexels) return a.edgeErrorTexels < b.edgeErrorTexels;
    if (a.biasTexels != b.biasTexels) return a.biasTexels < b.biasTexels;
    return a.acnePercent < b.acnePercent;
}

std::string receiverPlaneChoice(const TuneResult& result) {
    const std::optional<TuneStep>& off = result.bestByPlane[0];
    const std::optional<TuneStep>& on = result.bestByPlane[1];
    if (!off || !on) return {};
    const bool picked = betterCandidate(*on, *off);
    const TuneStep& a = picked ? *on : *off;
    const TuneStep& b = picked ? *off : *on;
    std::string why;
    if (a.withinLimit != b.withinLimit) why = "only it reaches the acne limit";
    else if (!a.withinLimit) why = "less acne";
    else if (a.wrongBeyondK != b.wrongBeyondK) why = "fewer wrong pixels beyond k";
    else if (a.edgeErrorTexels != b.edgeErrorTexels) why = "a smaller edge error";
    else why = "a smaller bias";
    char text[512];
    std::snprintf(text, sizeof text,
                  "receiver-plane bias %s (%s): with it slope %.3g, acne %.3f %%, leak %.3f %%, wrong %.3f %% "
                  "(%zu beyond k), edge %.2f texels; without it slope %.3g, acne %.3f %%, leak %.3f %%, wrong %.3f %% "
                  "(%zu beyond k), edge %.2f texels",
                  picked ? "kept" : "not kept", why.c_str(), double(on->slopeScaledDepthBias), on->acnePercent,
                  on->leakPercent, on->wrongPercent, on->wrongBeyondK, on->edgeErrorTexels,
                  double(off->slopeScaledDepthBias), off->acnePercent, off->leakPercent, off->wrongPercent,
                  off->wrongBeyondK, off->edgeErrorTexels);
    return text;
}

double tradeOffError(const TuneStep& s) { return s.soft ? s.softMeanError : s.meanError; }
double tradeOffBleeding(const TuneStep& s) { return s.soft ? s.bleedingPercent : s.leakPercent; }
double tradeOffDarkening(const TuneStep& s) { return s.soft ? s.overDarkeningPercent : s.acnePercent; }

bool betterTradeOff(const TuneStep& a, const TuneStep& b) {
    if (a.withinLimit != b.withinLimit) return a.withinLimit;
    const double ea = tradeOffError(a), eb = tradeOffError(b);
    if (!a.withinLimit) {
        if (limitingAcne(a) != limitingAcne(b)) return limitingAcne(a) < limitingAcne(b);
        return ea < eb;
    }
    if (std::abs(ea - eb) > kTradeOffTie * std::max(ea, eb)) return ea < eb;
    if (tradeOffBleeding(a) != tradeOffBleeding(b)) return tradeOffBleeding(a) < tradeOffBleeding(b);
    if (tradeOffDarkening(a) != tradeOffDarkening(b)) return tradeOffDarkening(a) < tradeOffDarkening(b);
    return ea < eb;
}

namespace {
constexpr std::pair<TuneSearch, const char*> kSearchNames[] = {
    {TuneSearch::Auto, "auto"}, {TuneSearch::Bias, "bias"}, {TuneSearch::TradeOff, "technique"},
    {TuneSearch::Both, "both"}};

// A trade-off key of the one light the tuner sees: "lights.#.size" is light 0's.
std::string tradeOffKeyOf(const TradeOffRange& range) {
    std::string key = range.key;
    if (const std::size_t at = key.find("#"); at != std::string::npos) key.replace(at, 1, "0");
    return key;
}
}  // namespace

namespace {
// The ranges a search of `scope` varies: a later light of several keeps the global keys tuned on the first.
std::vector<TradeOffRange> rangesIn(const TuneScope& scope, FilterKind kind) {
    std::vector<TradeOffRange> ranges;
    for (const TradeOffRange& range : filterTechnique(kind).tradeOff)
        if (scope.globalKeys || std::string(range.key).rfind("lights.#.", 0) == 0) ranges.push_back(range);
    return ranges;
}
}  // namespace

TuneSearch resolveTuneSearch(const TuneScope& scope, FilterKind kind) {
    if (scope.search != TuneSearch::Auto) return scope.search;
    return rangesIn(scope, kind).empty() ? TuneSearch::Bias : TuneSearch::TradeOff;
}

std::vector<std::string> tradeOffKeysOf(const TuneScope& scope, FilterKind kind) {
    std::vector<std::string> keys;
    for (const TradeOffRange& range : rangesIn(scope, kind)) keys.push_back(range.key);
    return keys;
}

std::string keyOfLight(const std::string& key, std::size_t index) {
    const std::string prefix = "lights.0.";
    return key.rfind(prefix, 0) == 0 ? "lights." + std::to_string(index) + "." + key.substr(prefix.size()) : key;
}

const char* tuneSearchName(TuneSearch search) {
    for (const auto& [value, name] : kSearchNames)
        if (value == search) return name;
    return "?";
}

std::optional<TuneSearch> parseTuneSearch(const std::string& name) {
    for (const auto& [value, text] : kSearchNames)
        if (name == text) return value;
    return std::nullopt;
}

TuneResult tuneBias(AccuracyMeter& meter, const Scene& scene, const Settings& start, const Camera& camera, int width,
                    int height, double maxAcnePercent, AccuracyProgress* progress,
                    std::function<void(const TuneStep&)> onStep, TuneScope scope) {
    const auto started = std::chrono::steady_clock::now();
    TuneResult result;
    result.best = start;
    result.closest = start;
    auto finish = [&] {
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        return result;
    };
    if (std::vector<std::string> problems = start.validate(); !problems.empty()) {
        result.error = "invalid settings: " + problems.front();
        return finish();
    }
    // One light: the caller isolates the light to tune (light_isolation.h) and writes the result back to it.
    if (std::string error = singleLightError(start, scene, "the bias search"); !error.empty()) {
        result.error = error;
        return finish();
    }
    if (!(maxAcnePercent >= 0.0)) {
        result.error = "the acne limit must be a percentage >= 0";
        return finish();
    }

    // What is searched: the technique's own trade-off (the keys its unit declares) and / or the depth bias.
    const FilterTechnique& technique = filterTechnique(start.filter.kind);
    const std::vector<TradeOffRange> ranges = rangesIn(scope, start.filter.kind);
    const TuneSearch search = resolveTuneSearch(scope, start.filter.kind);
    const bool biasSearch = search == TuneSearch::Bias || search == TuneSearch::Both;
    const bool tradeOffSearch = search == TuneSearch::TradeOff || search == TuneSearch::Both;
    if (tradeOffSearch && ranges.empty()) {
        result.error = std::string("filter.kind ") + technique.name +
                       (technique.tradeOff.empty() ? " declares no trade-off keys to tune"
                                                   : " declares only global trade-off keys, tuned on the first light") +
                       ": search the bias instead";
        return finish();
    }
    std::vector<const SettingsField*> tradeOffFields;
    for (const TradeOffRange& range : ranges) {
        const SettingsField* field = findSettingsField(tradeOffKeyOf(range));
        if (!field) {
            result.error = std::string("filter.kind ") + technique.name + "'s trade-off key " + range.key +
                           " is not a settings key";
            return finish();
        }
        tradeOffFields.push_back(field);
        result.tradeOffKeys.push_back(field->key);
    }

    // DepthBias units per texel, from the light space the renderer will build for these settings.
    Settings lit = start;
    lit = withEffectiveLights(start, scene);
    const glm::dvec3 origin = renderOriginOf(scene.bounds);
    std::string lightError;
    // A point light's six faces share near/far but see different receivers, a cascaded light's cascades have texels
    // of different sizes: the median of their figures.
    std::vector<LightSpace> spaces;
    const ViewCamera viewCamera = viewCameraOf(camera, double(width) / std::max(height, 1), origin);
    if (const auto views = buildLightViews(lit.lights[0], 0, scene.bounds, origin, &viewCamera, lightError))
        for (const ShadowView& view : *views) spaces.push_back(view.space);
    if (spaces.empty()) {
        result.error = lightError;
        return finish();
    }
    // At the receivers' actual depths: D32F's step follows the depth's exponent.
    std::vector<double> perView;
    for (const LightSpace& space : spaces) {
        const ReceiverDepths receivers = receiverDepths(scene, space, origin);
        const double texels = depthBiasUnitTexels(space, start.lights[0].shadow.format, receivers);
        if (receivers.valid && texels > 0.0) perView.push_back(texels);
    }
    std::sort(perView.begin(), perView.end());
    const double unitTexels = perView.empty() ? 0.0 : perView[perView.size() / 2];
    if (biasSearch && !(unitTexels > 0.0)) {
        result.error = "cannot relate DepthBias to texels for this light";
        return finish();
    }

    auto settingsFor = [&](const Candidate& c, Variant v) {
        Settings s = start;
        s.lights[0].shadow.cullMode = v.cull;
        s.lights[0].shadow.receiverPlaneBias = v.plane;
        s.lights[0].shadow.depthBias = float(std::min(c.constantTexels / unitTexels, kMaxDepthBiasUnits));
        s.lights[0].shadow.slopeScaledDepthBias = float(std::min(c.slope, kMaxSlope));
        s.lights[0].shadow.normalOffset = float(std::min(c.normal, kMaxNormalTexels));
        return s;
    };

    std::optional<std::size_t> bestIndex;  // into result.path, of the current search
    std::size_t lastCulled = 0;            // wrong pixels the last candidate's culled casters cause
    bool stop = false;
    int plannedSteps = biasSearch ? kMaxSteps : 0;
    for (const TradeOffRange& range : ranges)  // two rounds at most
        plannedSteps += 2 * int(tradeOffCandidates(range, start).size());
    // The search's order: the bias criterion, then (for the trade-off search) betterTradeOff.
    bool (*better)(const TuneStep&, const TuneStep&) = betterCandidate;
    bool tradeOffPhase = false;
    // Measures one candidate; returns whether its acne is within the limit (nullopt: failed or cancelled).
    auto measure = [&](const std::string& phase, const Settings& s, double magnitude) -> std::optional<bool> {
        if (stop) return std::nullopt;
        if (progress && progress->cancel.load()) {
            stop = true;
            result.cancelled = true;
            result.error = "cancelled";
            return std::nullopt;
        }
        // The first candidate builds the reference (the long part); the rest share what is left of the bar.
        if (progress) {
            const std::size_t done = result.path.size();
            // What is left of the bar is shared by the steps still planned, so it only moves forward when the
            // cull-mode search adds steps.
            plannedSteps = std::max(plannedSteps, int(done) + 1);
            progress->base = done == 0 ? 0.0f : progress->base + progress->span;
            progress->span = done == 0 ? kFirstShare
                                       : (1.0f - progress->base) / float(std::max(1, plannedSteps - int(done) + 1));
        }
        AccuracyReport report = meter.measure(scene, s, camera, width, height, progress);
        if (!report.ok) {
            stop = true;
            result.cancelled = report.cancelled;
            result.error = report.error;
            return std::nullopt;
        }
        if (result.path.empty()) result.referenceCost = report.cost;
        TuneStep step;
        step.index = int(result.path.size()) + 1;
        step.phase = phase;
        step.depthBias = s.lights[0].shadow.depthBias;
        step.slopeScaledDepthBias = s.lights[0].shadow.slopeScaledDepthBias;
        step.normalOffset = s.lights[0].shadow.normalOffset;
        step.cullMode = s.lights[0].shadow.cullMode;
        step.receiverPlaneBias = s.lights[0].shadow.receiverPlaneBias;
        step.biasTexels = magnitude;
        step.acnePercent = report.acnePercent;
        step.leakPercent = report.leakPercent;
        step.wrongPercent = report.wrongPercent;
        step.wrongBeyondK = report.counts.wrongBeyondK;
        step.meanError = report.meanError;
        step.edgeErrorTexels = report.edgeErrorP95Texels;
        step.withinLimit = report.acnePercent <= maxAcnePercent;
        step.tradeOffStep = tradeOffPhase;
        if (tradeOffPhase)
            for (const SettingsField* field : tradeOffFields) step.tradeOff.push_back(field->get(s).get<double>());
        if (report.soft.measured) {
            step.soft = true;
            step.softMeanError = report.soft.meanError;
            step.softWrongPercent = report.soft.wrongPercent;
            step.bleedingPercent = report.soft.bleedingPercent;
            step.overDarkeningPercent = report.soft.overDarkeningPercent;
            step.penumbraErrorWorld = report.soft.penumbra.errorWorld;
        }
        step.costMs = report.cost.totalMs;
        step.toolFrameMs = report.cost.toolFrameMs;
        // A cascaded light: one setting for every cascade, each judged on the pixels it holds.
        for (const CascadeNumbers& c : report.cascades.cascades) {
            step.cascadeAcnePercent.push_back(c.acnePercent);
            if (c.measured < kTuneCascadeMinPixels) continue;
            if (step.worstCascade < 0 || c.acnePercent > step.cascadeAcnePercent[std::size_t(step.worstCascade)])
                step.worstCascade = c.cascade;
            step.withinLimit = step.withinLimit && c.acnePercent <= maxAcnePercent;
        }
        lastCulled = report.counts.causeWrong[std::size_t(MismatchCause::CasterCulled)];
        if (!bestIndex || better(step, result.path[*bestIndex])) {
            step.bestSoFar = true;
            bestIndex = result.path.size();
            result.closest = s;
            result.report = std::move(report);
        }
        result.path.push_back(step);
        if (progress) {
            progress->setStage("candidate " + std::to_string(step.index) + ": " + phase);
        }
        if (onStep) onStep(step);
        return step.withinLimit;
    };

    bool planeApplies = false;  // the bias search ran both ways of receiver-plane bias
    if (biasSearch) {
        // 1. The given preset, and no bias at all.
        const Candidate given{double(start.lights[0].shadow.depthBias) * unitTexels, start.lights[0].shadow.slopeScaledDepthBias,
                              start.lights[0].shadow.normalOffset};
        const Variant startVariant{start.lights[0].shadow.cullMode, start.lights[0].shadow.receiverPlaneBias};
        measure("start (the given settings)", start, given.magnitude());
        std::size_t culled = lastCulled;
        const std::optional<bool> zeroPasses = measure("zero bias", settingsFor({}, startVariant), 0.0);
        if (stop) return finish();
        culled = std::max(culled, lastCulled);

        // 2. Culled casters cause wrong pixels: the other cull modes join the search when they cull less.
        std::vector<std::pair<Variant, bool>> modes = {{startVariant, zeroPasses.value_or(false)}};
        if (culled > 0) {
            for (CullMode mode : {CullMode::None, CullMode::Back, CullMode::Front}) {
                if (mode == startVariant.cull) continue;
                const Variant v{mode, startVariant.plane};
                const std::optional<bool> passes =
                    measure(std::string("zero bias, cull ") + cullModeName(mode), settingsFor({}, v), 0.0);
                if (stop) return finish();
                if (lastCulled < culled) {
                    modes.emplace_back(v, passes.value_or(false));
                    plannedSteps += 4 * (10 + kBisections);
                }
            }
        }
        // 2b. A filter whose taps spread (PCF, Poisson) on a directional or spot light: the search runs with
        //     receiver-plane bias the other way too, and the usual criterion picks between them.
        planeApplies = technique.receiverPlane && lit.lights[0].type != LightType::Point;
        if (planeApplies) {
            const std::size_t count = modes.size();
            for (std::size_t i = 0; i < count; ++i) {
                const Variant v{modes[i].first.cull, !modes[i].first.plane};
                const std::optional<bool> passes =
                    measure(std::string("zero bias, receiver plane ") + (v.plane ? "on" : "off"), settingsFor({}, v), 0.0);
                if (stop) return finish();
                modes.emplace_back(v, passes.value_or(false));
                plannedSteps += 4 * (10 + kBisections);
            }
        }

        // 3. Along each direction: double until acne is within the limit, then bisect back toward the smallest bias
        //    that still is (leak only grows with bias, so that is the family's least-leak setting).
        const double kRide = 0.02;  // a hair of constant bias: slope alone does nothing on receivers facing the light
        const std::vector<Family> families = {
            {"slope", [&](double t) { return Candidate{kRide, t, 0.0}; }, kMaxSlope},
            {"normal offset", [](double t) { return Candidate{0.0, 0.0, t}; }, kMaxNormalTexels},
            {"slope + normal offset", [&](double t) { return Candidate{kRide, t, t / 2.0}; }, kMaxSlope},
            {"constant", [](double t) { return Candidate{t, 0.0, 0.0}; }, kMaxDepthBiasUnits * unitTexels},
        };
        for (const auto& [mode, passesAtZero] : modes) {
            if (passesAtZero) continue;
            std::string suffix = mode.cull == startVariant.cull ? "" : std::string(", cull ") + cullModeName(mode.cull);
            if (mode.plane != startVariant.plane) suffix += mode.plane ? ", receiver plane" : ", no receiver plane";
            for (const Family& family : families) {
                double failing = 0.0, passing = -1.0;
                for (double t = 0.25;; t = std::min(t * 2.0, family.tMax)) {
                    const Candidate c = family.at(t);
                    const std::optional<bool> ok =
                        measure(std::string("grow ") + family.name + suffix, settingsFor(c, mode), c.magnitude());
                    if (stop) return finish();
                    if (*ok) {
                        passing = t;
                        break;
                    }
                    failing = t;
                    if (t >= family.tMax) break;
                }
                if (passing < 0.0) continue;
                for (int i = 0; i < kBisections; ++i) {
                    const double mid = 0.5 * (failing + passing);
                    const Candidate c = family.at(mid);
                    const std::optional<bool> ok =
                        measure(std::string("bisect ") + family.name + suffix, settingsFor(c, mode), c.magnitude());
                    if (stop) return finish();
                    (*ok ? passing : failing) = mid;
                }
            }
        }
    }

    // 4. The technique's own trade-off, from the bias found (or the given settings): one key at a time over its
    //    declared candidates, the others at the best so far; a second round when the first moved a key.
    if (tradeOffSearch) {
        Settings from = biasSearch ? result.closest : start;
        // A start value above what the settings can use is lowered to it (the renderer would clamp it anyway):
        // the tuner never proposes a value it would clamp.
        for (std::size_t k = 0; k < ranges.size(); ++k) {
            const double value = tradeOffFields[k]->get(from).get<double>();
            const double top = tradeOffTop(ranges[k], from);
            if (value <= top) continue;
            tradeOffFields[k]->set(from, top);
            char text[200];
            std::snprintf(text, sizeof text, "%s %g lowered to %g (what these settings use)",
                          tradeOffFields[k]->key.c_str(), value, top);
            result.startClamps.push_back(text);
        }
        tradeOffPhase = true;
        better = betterTradeOff;
        bestIndex.reset();
        std::map<std::vector<double>, bool> seen;  // the candidates measured (by their trade-off values)
        auto valuesOf = [&](const Settings& s) {
            std::vector<double> values;
            for (const SettingsField* field : tradeOffFields) values.push_back(field->get(s).get<double>());
            return values;
        };
        auto tryCandidate = [&](const std::string& phase, const Settings& s) {
            if (!seen.emplace(valuesOf(s), true).second) return;
            measure(phase, s, 0.0);
        };
        tryCandidate(biasSearch ? "trade-off start (the bias found)" : "start (the given settings)", from);
        if (stop) return finish();
        for (int round = 0; round < 2; ++round) {
            const std::vector<double> before = result.path[*bestIndex].tradeOff;
            for (std::size_t k = 0; k < ranges.size(); ++k) {
                const Settings centre = result.closest;  // the best so far: every other key at its best
                for (double value : tradeOffCandidates(ranges[k], centre)) {
                    Settings s = centre;
                    if (std::string error = tradeOffFields[k]->set(s, value); !error.empty()) {
                        result.error = std::string("filter.kind ") + technique.name + "'s trade-off range: " + error;
                        return finish();
                    }
                    tryCandidate("trade-off " + tradeOffFields[k]->key, s);
                    if (stop) return finish();
                }
            }
            if (result.path[*bestIndex].tradeOff == before) break;
        }
        result.tradeOffSearched = true;
    }

    for (const TuneStep& step : result.path) {
        if (step.tradeOffStep) continue;
        std::optional<TuneStep>& best = result.bestByPlane[step.receiverPlaneBias ? 1 : 0];
        if (!best || betterCandidate(step, *best)) best = step;
    }
    if (!planeApplies) result.bestByPlane[0] = result.bestByPlane[1] = std::nullopt;
    result.reachedLimit = bestIndex && result.path[*bestIndex].withinLimit;
    if (result.reachedLimit) {
        result.best = result.closest;
    } else {
        // A cascaded light: the cascade that stops it (its worst judged cascade, when that one is above the limit).
        const TuneStep& closest = result.path[*bestIndex];
        if (closest.worstCascade >= 0 &&
            closest.cascadeAcnePercent[std::size_t(closest.worstCascade)] > maxAcnePercent) {
            const CascadeNumbers& c = result.report.cascades.cascades[std::size_t(closest.worstCascade)];
            result.blockingCascade = c.cascade;
            result.blockingCascadeTexel = c.texelWorldSize;
            result.blockingCascadePixels = c.measured;
            result.blockingCascadeAcne = c.acnePercent;
            result.blockingCascadeLeastAcne = c.acnePercent;
            for (const TuneStep& step : result.path)
                if (std::size_t(c.cascade) < step.cascadeAcnePercent.size())
                    result.blockingCascadeLeastAcne =
                        std::min(result.blockingCascadeLeastAcne, step.cascadeAcnePercent[std::size_t(c.cascade)]);
        }
        // What keeps the least-acne candidate's acne up: the cause of most of its acne pixels.
        std::size_t most = 0;
        for (MismatchCause cause : {MismatchCause::SelfShadowing, MismatchCause::AlphaTest,
                                    MismatchCause::OutsideVolume}) {
            const std::size_t n = result.report.counts.causePixels[std::size_t(cause)];
            if (n > most) {
                most = n;
                result.blockingCause = cause;
            }
        }
    }
    result.ok = true;
    if (progress) {
        progress->base = 0.0f;
        progress->span = 1.0f;
        progress->fraction = 1.0f;
        progress->setStage(result.reachedLimit ? "done" : "done: no setting reached the acne limit");
    }
    return finish();
}

}  // namespace shadowlab
