#pragma once
// How the accuracy commands print and save an AccuracyReport: the numbers with the counts behind them, what the
// reference cost, and the same as JSON.
#include "accuracy/accuracy_meter.h"
#include "accuracy/accuracy_overlay.h"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace shadowlab::cli {

void printAccuracy(std::ostream& out, const AccuracyReport& report);
// "red = acne, blue = leak, ..." for a legend (accuracy_overlay.h's colours).
std::string legendText(OverlayKind kind);
void printAccuracyCost(std::ostream& out, const AccuracyReport& report);
nlohmann::json accuracyToJson(const AccuracyReport& report);

}  // namespace shadowlab::cli
