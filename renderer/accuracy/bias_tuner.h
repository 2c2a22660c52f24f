#pragma once
// Suggests DepthBias, SlopeScaledDepthBias and normal offset: the setting with the least leak whose acne is at most
// maxAcnePercent, found by measuring candidates with an AccuracyMeter (each costs one tool frame: the reference is
// cached). Other settings are kept as given.
#include "accuracy/accuracy_meter.h"

#include <functional>
#include <string>
#include <vector>

namespace shadowlab {

struct TuneStep {
    int index = 0;                   // 1-based candidate number
    std::string phase;               // what the search was doing, e.g. "start", "zero bias", "grow slope", "bisect"
    float depthBias = 0.0f;          // D3D DepthBias (format depth steps)
    float slopeScaledDepthBias = 0.0f;
    float normalOffset = 0.0f;       // texels
    double acnePercent = 0.0;
    double leakPercent = 0.0;
    double faintAcnePercent = 0.0;
    std::size_t mismatched = 0;
    bool withinLimit = false;        // acnePercent <= maxAcnePercent
    bool bestSoFar = false;          // this candidate became the best so far
};

struct TuneResult {
    bool ok = false;
    bool cancelled = false;
    std::string error;               // when !ok
    Settings best;                   // start with the best DepthBias / slope / normal offset found
    bool reachedLimit = false;       // false: no candidate reached acne <= maxAcnePercent; best has the least acne
    std::vector<TuneStep> path;      // every candidate measured, in order
    AccuracyReport report;           // the measurement of `best`
    double seconds = 0.0;            // wall time of the search
    AccuracyCost referenceCost;      // what the first measurement (which built the reference) cost
};

TuneResult tuneBias(AccuracyMeter& meter, const Scene& scene, const Settings& start, const Camera& camera, int width,
                    int height, double maxAcnePercent = 0.1, AccuracyProgress* progress = nullptr,
                    std::function<void(const TuneStep&)> onStep = {});

}  // namespace shadowlab
