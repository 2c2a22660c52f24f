#pragma once
// `shadowlab measure --remeasure-bench N`: what live accuracy costs. After the full measure (which caches the
// reference), N re-measures after a bias change each (shadow.depthBias alternating between two nearby values, so
// every round re-renders the shadow map), timed on the GPU path (AccuracyMeter::remeasure: one tool frame, a compute
// count, a few words read back) and on the CPU path (AccuracyMeter::measure with the reference reused: the frame read
// back and every pixel compared on the CPU), and whether both give the same counts.
#include "accuracy/accuracy_meter.h"

#include <ostream>

namespace shadowlab::cli {

// Prints the figures; returns false when a re-measure failed or the two paths disagree (the message says which).
bool runRemeasureBench(std::ostream& out, AccuracyMeter& meter, const Scene& scene, const Settings& settings,
                       const Camera& camera, int width, int height, int rounds);

}  // namespace shadowlab::cli
