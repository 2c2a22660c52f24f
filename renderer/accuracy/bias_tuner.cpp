#include "accuracy/bias_tuner.h"

#include "light/depth_bias.h"
#include "light/light_space.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
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
constexpr float kFirstShare = 0.3f;                    // of the progress bar: the first candidate's reference

// One search direction: the bias grows with t along it.
struct Family {
    const char* name;
    std::function<Candidate(double t)> at;
    double tMax;
};

// Is step a better suggestion than b? Within the acne limit first, then least leak, least faint acne, fewest
// mismatched pixels and the smallest bias; outside the limit, least acne first.
bool better(const TuneStep& a, double aMagnitude, const TuneStep& b, double bMagnitude) {
    if (a.withinLimit != b.withinLimit) return a.withinLimit;
    if (!a.withinLimit && a.acnePercent != b.acnePercent) return a.acnePercent < b.acnePercent;
    if (a.leakPercent != b.leakPercent) return a.leakPercent < b.leakPercent;
    if (a.faintAcnePercent != b.faintAcnePercent) return a.faintAcnePercent < b.faintAcnePercent;
    if (a.mismatched != b.mismatched) return a.mismatched < b.mismatched;
    return aMagnitude < bMagnitude;
}

}  // namespace

TuneResult tuneBias(AccuracyMeter& meter, const Scene& scene, const Settings& start, const Camera& camera, int width,
                    int height, double maxAcnePercent, AccuracyProgress* progress,
                    std::function<void(const TuneStep&)> onStep) {
    const auto started = std::chrono::steady_clock::now();
    TuneResult result;
    result.best = start;
    auto finish = [&] {
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        return result;
    };
    if (std::vector<std::string> problems = start.validate(); !problems.empty()) {
        result.error = "invalid settings: " + problems.front();
        return finish();
    }
    if (!(maxAcnePercent >= 0.0)) {
        result.error = "the acne limit must be a percentage >= 0";
        return finish();
    }

    // DepthBias units per texel, from the light space the renderer will build for these settings.
    Settings lit = start;
    lit.light = effectiveLight(start, scene);
    const glm::dvec3 origin = scene.bounds.empty ? glm::dvec3(0.0) : glm::dvec3(scene.bounds.center());
    std::string lightError;
    const std::optional<LightSpace> lightSpace = buildLightSpace(lit, scene.bounds, origin, lightError);
    if (!lightSpace) {
        result.error = lightError;
        return finish();
    }
    // At the receivers' actual depths: D32F's step follows the depth's exponent.
    const double unitTexels =
        depthBiasUnitTexels(*lightSpace, start.shadow.format, receiverDepths(scene, *lightSpace, origin));
    if (!(unitTexels > 0.0)) {
        result.error = "cannot relate DepthBias to texels for this light";
        return finish();
    }

    auto settingsFor = [&](const Candidate& c) {
        Settings s = start;
        s.shadow.depthBias = float(std::min(c.constantTexels / unitTexels, kMaxDepthBiasUnits));
        s.shadow.slopeScaledDepthBias = float(std::min(c.slope, kMaxSlope));
        s.shadow.normalOffset = float(std::min(c.normal, kMaxNormalTexels));
        return s;
    };

    std::optional<std::size_t> bestIndex;  // into result.path
    double bestMagnitude = 0.0;
    bool stop = false;
    // Measures one candidate; returns whether its acne is within the limit (nullopt: failed or cancelled).
    auto measure = [&](const char* phase, const Settings& s, double magnitude) -> std::optional<bool> {
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
            progress->base = done == 0 ? 0.0f : kFirstShare + (1.0f - kFirstShare) * float(done - 1) / kMaxSteps;
            progress->span = done == 0 ? kFirstShare : (1.0f - kFirstShare) / kMaxSteps;
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
        step.depthBias = s.shadow.depthBias;
        step.slopeScaledDepthBias = s.shadow.slopeScaledDepthBias;
        step.normalOffset = s.shadow.normalOffset;
        step.acnePercent = report.acnePercent;
        step.leakPercent = report.leakPercent;
        step.faintAcnePercent = report.faintAcnePercent;
        step.mismatched = report.counts.mismatched;
        step.withinLimit = report.acnePercent <= maxAcnePercent;
        if (!bestIndex || better(step, magnitude, result.path[*bestIndex], bestMagnitude)) {
            step.bestSoFar = true;
            bestIndex = result.path.size();
            bestMagnitude = magnitude;
            result.best = s;
            result.report = std::move(report);
        }
        result.path.push_back(step);
        if (progress) {
            progress->setStage("candidate " + std::to_string(step.index) + ": " + phase);
        }
        if (onStep) onStep(step);
        return step.withinLimit;
    };

    // 1. The given preset, and no bias at all.
    const Candidate given{double(start.shadow.depthBias) * unitTexels, start.shadow.slopeScaledDepthBias,
                          start.shadow.normalOffset};
    measure("start (the given settings)", start, given.magnitude());
    const std::optional<bool> zeroPasses = measure("zero bias", settingsFor({}), 0.0);
    if (stop) return finish();

    // 2. Along each direction: double until acne is within the limit, then bisect back toward the smallest bias
    //    that still is (leak only grows with bias, so that is the family's least-leak setting).
    const double kRide = 0.02;  // a hair of constant bias: slope alone does nothing on receivers facing the light
    const std::vector<Family> families = {
        {"slope", [&](double t) { return Candidate{kRide, t, 0.0}; }, kMaxSlope},
        {"normal offset", [](double t) { return Candidate{0.0, 0.0, t}; }, kMaxNormalTexels},
        {"slope + normal offset", [&](double t) { return Candidate{kRide, t, t / 2.0}; }, kMaxSlope},
        {"constant", [](double t) { return Candidate{t, 0.0, 0.0}; }, kMaxDepthBiasUnits * unitTexels},
    };
    if (!zeroPasses.value_or(false)) {
        for (const Family& family : families) {
            double failing = 0.0, passing = -1.0;
            for (double t = 0.25;; t = std::min(t * 2.0, family.tMax)) {
                const Candidate c = family.at(t);
                const std::string phase = std::string("grow ") + family.name;
                const std::optional<bool> ok = measure(phase.c_str(), settingsFor(c), c.magnitude());
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
                const std::string phase = std::string("bisect ") + family.name;
                const std::optional<bool> ok = measure(phase.c_str(), settingsFor(c), c.magnitude());
                if (stop) return finish();
                (*ok ? passing : failing) = mid;
            }
        }
    }

    result.reachedLimit = bestIndex && result.path[*bestIndex].withinLimit;
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
