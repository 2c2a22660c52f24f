#pragma once
// How the accuracy commands print and save an AccuracyReport: the numbers with the counts behind them, what the
// reference cost, and the same as JSON.
#include "accuracy/accuracy_meter.h"
#include "accuracy/accuracy_overlay.h"
#include "accuracy/light_accuracy.h"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace shadowlab::cli {

void printAccuracy(std::ostream& out, const AccuracyReport& report);
// "red = acne, blue = leak, ..." for a legend (accuracy_overlay.h's colours).
std::string legendText(OverlayKind kind);
std::string legendText(const std::vector<LegendEntry>& legend);
void printAccuracyCost(std::ostream& out, const AccuracyReport& report);
nlohmann::json accuracyToJson(const AccuracyReport& report);
// The headline numbers (acne, severity, leak, wrong pixels, mean error, edge error), as accuracyToJson names them.
nlohmann::json numbersToJson(const AccuracyNumbers& numbers);

// "lights.1 (spot)": how reports name a light.
std::string lightLabel(std::size_t index, LightType type);
// Every measured light (its numbers and cost), the lights not measured and why, then the whole picture.
void printManyLights(std::ostream& out, const ManyLightsReport& many);
// {"lights": [{index, type, ...accuracyToJson}], "notMeasured": [...], "whole": {...}, metricsVersion, width, height}
nlohmann::json manyLightsToJson(const ManyLightsReport& many);

}  // namespace shadowlab::cli
