#pragma once
// How `measure --motion` prints and saves a FlickerReport (renderer/accuracy/flicker.h): flicker beside the share of
// pixels whose true visibility changed, mean |dS|, the step in texels, each pair's figures; the same as JSON.
#include "accuracy/flicker.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace shadowlab::cli {

void printFlicker(std::ostream& out, const FlickerReport& report);
nlohmann::json flickerToJson(const FlickerReport& report);

}  // namespace shadowlab::cli
