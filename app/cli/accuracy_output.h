#pragma once
// How the accuracy commands print and save an AccuracyReport: the numbers with the counts behind them, what the
// reference cost, and the same as JSON.
#include "accuracy/accuracy_meter.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace shadowlab::cli {

void printAccuracy(std::ostream& out, const AccuracyReport& report);
void printAccuracyCost(std::ostream& out, const AccuracyReport& report);
nlohmann::json accuracyToJson(const AccuracyReport& report);

}  // namespace shadowlab::cli
