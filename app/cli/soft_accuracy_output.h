#pragma once
// How the accuracy commands print and save the soft numbers of a light of size > 0 (metrics version 3,
// accuracy/soft_metrics.h): which light, its size and ray count, every number with what it describes.
#include "accuracy/soft_metrics.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace shadowlab::cli {

// Nothing for a hard light (soft.measured false).
void printSoftAccuracy(std::ostream& out, const SoftAccuracy& soft);
// {"light", "size", "sizeUnit", "rays", "metricsVersion": 3, the numbers, "penumbraWidth": {...}, "counts", cost}.
nlohmann::json softAccuracyToJson(const SoftAccuracy& soft);

}  // namespace shadowlab::cli
