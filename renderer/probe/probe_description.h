#pragma once
// A pixel probe's report in words (the CLI prints these lines, the editor's Probe panel shows them) and as JSON:
// the one place its fields are named.
#include "probe/pixel_probe.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace shadowlab {

// The headline, e.g. "S = 0.333 (GPU 0.333, agree): 3 of 9 taps lit".
std::string probeSummary(const PixelProbeReport& report);

// Every section: surface, light space, receiver depth, bias terms, taps (one line each), S, the measurement.
std::vector<std::string> describeProbe(const PixelProbeReport& report);

// One tap as a line: offset, texel(s), stored depths, comparisons.
std::string describeTap(const PixelProbeReport& report, const ProbeTap& tap);

nlohmann::json probeToJson(const PixelProbeReport& report);

}  // namespace shadowlab
