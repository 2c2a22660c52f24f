#pragma once
// `shadowlab tune`: searches DepthBias, SlopeScaledDepthBias and normal offset for the least leak with acne at most
// --max-acne percent, prints progress, the path and the result, and writes the result as a preset.
#include <string>
#include <vector>

namespace shadowlab::cli {

struct TuneOptions {
    std::string scene = "builtin:textbook";
    std::string preset;
    std::vector<std::string> overrides;
    int width = 640;
    int height = 360;
    std::string out = "tuned.json";
    double maxAcnePercent = 0.1;
    std::string json;  // optional: the path and the result as JSON
};

// Exit code 0 unless it failed; reaching no setting within the acne limit is reported, not a failure.
int runTune(const TuneOptions& options);

}  // namespace shadowlab::cli
