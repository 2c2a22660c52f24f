#pragma once
// DESIGN.md's accuracy measures, version 2, from per-pixel buffers (no GL: unit-testable on synthetic buffers).
// e = one 8-bit step (1/255), k = filter radius + 1 texel, dist = distance to the true shadow boundary in texels.
//   acne  = #{V=1, S<1-e, dist>k} / #{V=1}   (severity: mean 1-S over them)
//   leak  = #{V=0, S>e,   dist>k} / #{V=0}
//   wrong pixels = #{|S-V| >= 0.5} / #measured,  mean error = mean |S-V| over measured (edges included)
//   edge error = 95th percentile of dist over mismatched pixels (|S-V| > e), in texels, world units, screen pixels
// Every mismatched pixel gets a cause (mismatch_cause.h).
#include "accuracy/accuracy_meter.h"
#include "accuracy/mismatch_cause.h"
#include "reference/visibility.h"

#include <functional>
#include <vector>

namespace shadowlab {

// The thresholds of the definitions, shared by the CPU metrics and the GPU counter (gpu_accuracy_counter.h hands them
// to its shader as uniforms, so both compare against the very same float values).
inline constexpr float kVisibleStep = 1.0f / 255.0f;         // e: one 8-bit step
inline constexpr float kLitBelow = 1.0f - kVisibleStep;      // a truly lit pixel with S below this is visibly darker
inline constexpr double kWrongError = 0.5;                   // |S-V| from which a pixel counts as wrong
inline constexpr int kEdgeErrorPercentile = 95;              // edge error = this percentile of dist

// How far a filter reads from the lookup position, in texels: point 0, hardware 2x2 1 (bilinear neighbours),
// N x N PCF (N-1)/2, Poisson its radius + 1 (its taps are bilinear).
double filterRadiusTexels(const FilterSettings& filter);
inline double acceptanceRadiusTexels(const FilterSettings& filter) { return filterRadiusTexels(filter) + 1.0; }

// Is the tool's S visibly different from the reference (one 8-bit step or more toward the wrong side)?
inline bool visiblyWrong(bool lit, float s) { return lit ? s < kLitBelow : s > kVisibleStep; }

struct MetricsInput {
    const std::vector<PixelClass>* classes = nullptr;  // the reference's verdict per pixel
    const std::vector<float>* shadowFactor = nullptr;  // the tool's S per pixel
    const std::vector<std::uint8_t>* toolCovered = nullptr;  // the tool's frame drew a surface there
    double k = 1.0;
    // Pixel i's distance to the true boundary in texels (asked only for mismatched pixels).
    std::function<double(std::size_t)> distance;
    // Optional: pixel i's cause (asked only for mismatched pixels, with its distance); NearEdge / SelfShadowing /
    // BiasOverGap by distance and side when absent.
    std::function<MismatchCause(std::size_t, double)> cause;
    // Optional: world units per texel and per screen pixel at pixel i (edge error in those units; 0 when absent).
    std::function<double(std::size_t)> worldPerTexel;
    std::function<double(std::size_t)> worldPerPixel;
};

struct MetricsResult : AccuracyNumbers {
    std::vector<std::uint8_t> measured;  // per pixel: 1 when scored (counted in counts.measured)
    std::vector<PixelMark> marks;        // per pixel, for the error overlay
    std::vector<MismatchCause> causes;   // per pixel, for the cause overlay
};

// counts.boundaryPixels and counts.shadowedNearEdge are left for the caller. Runs on every core: the input's functions
// are called from several threads at once (for different pixels).
MetricsResult computeMetrics(const MetricsInput& input);

// The 0-based index of the p-th percentile (0..100) of n sorted values by nearest rank, ceil(p n / 100) - 1 (at
// least 0), in integers so the GPU counter picks the very same element.
std::size_t nearestRankIndex(std::size_t n, int percent);

// The p-th percentile (0..100) by nearest rank; 0 for an empty list. Reorders values.
double percentile(std::vector<double>& values, int percent);

// The percentages and means of AccuracyNumbers from its counts and the sums of |S-V| (measured pixels) and of 1-S
// (acne pixels): the one place both the CPU metrics and the GPU counter turn counts into numbers.
void setRatios(AccuracyNumbers& numbers, double errorSum, double severitySum);

}  // namespace shadowlab
