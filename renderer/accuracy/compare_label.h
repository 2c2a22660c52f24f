#pragma once
// The label lines of one side of an A/B comparison (its name, pass times, and accuracy once measured): one wording
// for `shadowlab render --compare` and the editor's split view.
#include "accuracy/accuracy_meter.h"
#include "frame/frame_stats.h"

#include <string>
#include <vector>

namespace shadowlab {

// {"A: name", "shadow 0.42 ms, main 1.10 ms (GPU)"}; "n/a" for a pass without a timing yet.
std::vector<std::string> compareLabel(const std::string& side, const std::string& name, const FrameStats& stats);

// "acne 0.012 %, leak 0.000 %, wrong 0.340 %"
std::string accuracyLine(const AccuracyNumbers& numbers);

}  // namespace shadowlab
