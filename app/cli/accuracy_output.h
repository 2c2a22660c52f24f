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

// "" when a file can be created at path (its folder exists), else why not — checked before the work starts.
std::string checkOutputFolder(const std::string& path, const char* option);

// Writes text to path through a temporary file and a rename; "" or an error naming the file.
std::string writeTextFile(const std::string& path, const std::string& text);

}  // namespace shadowlab::cli
