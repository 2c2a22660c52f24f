#pragma once
// The cache error of a shadow.update policy (issue 22, "What it measures"): a frame drawn from the policy's kept maps
// against the same frame with every view re-rendered, compared at the same pixels. A pixel is wrong when the two
// shadow factors differ by measure's wrong-pixel threshold (|S - S_full| >= kWrongError); the mean is |S - S_full|
// over the pixels both measure. The full re-render is the exact baseline: whatever the policy gets wrong beyond it is
// what its cache costs (everyFrame and onChange read 0; everyNthFrame and a caster flagged static that moves do
// not). No GL: it compares two AccuracyMeter reports of one view.
#include "accuracy/accuracy_meter.h"

#include <cstddef>

namespace shadowlab {

struct CacheError {
    std::size_t measured = 0;  // pixels measured in both frames
    std::size_t wrong = 0;     // |S - S_full| >= kWrongError
    double wrongPercent = 0.0;
    double meanError = 0.0;    // mean |S - S_full|
};

// `cached` and `full`: the same view (size, camera, pose), with their per-pixel data (measure(), not remeasure()).
CacheError cacheErrorAgainst(const AccuracyReport& cached, const AccuracyReport& full);

}  // namespace shadowlab
