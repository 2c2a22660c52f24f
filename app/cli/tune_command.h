#pragma once
// `shadowlab tune`: searches DepthBias, SlopeScaledDepthBias, normal offset (and the cull mode when culled casters
// cause wrong pixels) for acne at most --max-acne percent with the fewest wrong pixels beyond k, prints the path and
// the result, and writes the result as a preset. When no setting reaches the limit it names the cause that stops it
// and writes no preset.
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

// Exit code: 0 with a result, kNoSettingReachedLimit when no setting reached the limit (no preset written), other
// non-zero codes for bad input or failures.
inline constexpr int kNoSettingReachedLimit = 3;
int runTune(const TuneOptions& options);

}  // namespace shadowlab::cli
