#pragma once
// `shadowlab tune`: searches DepthBias, SlopeScaledDepthBias, normal offset (and the cull mode when culled casters
// cause wrong pixels) for acne at most --max-acne percent with the fewest wrong pixels beyond k, and / or (--search)
// the filter technique's own trade-off keys for acne within the limit and then the least (soft) error; prints the
// path with each candidate's cost and the result, and writes the result as a preset. When no setting reaches the limit it names the cause that stops it
// and writes no preset. Each light is tuned alone (its shadow factor does not depend on the other lights:
// renderer/accuracy/light_isolation.h): --light N tunes light N, the default tunes every shadow-casting light in
// turn; the preset keeps every other setting and gets each tuned light's bias in lights[N].shadow.
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
    int light = -1;    // --light N: only light N; -1 = every shadow-casting light in turn
    // --search: auto, bias, technique, both (accuracy/bias_tuner.h's TuneSearch). Global technique keys (filter.*)
    // are tuned on the first light tuned; later lights search their bias and their own per-light keys.
    std::string search = "auto";
};

// Exit code: 0 with a result, kNoSettingReachedLimit when some tuned light reached no setting within the limit (no
// preset written), other
// non-zero codes for bad input or failures.
inline constexpr int kNoSettingReachedLimit = 3;
int runTune(const TuneOptions& options);

}  // namespace shadowlab::cli
