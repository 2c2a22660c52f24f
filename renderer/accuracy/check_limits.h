#pragma once
// A check case's figures against its limits: each measured light's acne, leak, wrong pixels and edge error (and the
// whole picture's acne, leak and wrong pixels when several lights are measured), each light's flicker. Each figure
// says what it describes (its subject: "lights.1 (spot)", "whole picture"), so a report names which light broke
// which limit. No GL.
#include "accuracy/accuracy_meter.h"
#include "accuracy/check_case.h"

#include <string>
#include <vector>

namespace shadowlab {

struct CheckFigure {
    std::string subject;  // "lights.0 (directional)", "whole picture", "lights.0 (directional) under light motion"
    const CheckLimitInfo* limit = nullptr;
    double value = 0.0;
    double max = 0.0;
    // Above the limit, or not a number (a figure that cannot be judged fails).
    bool broken() const { return !(value <= max); }
};

// The figures `limits` bounds among acne, leak, wrong pixels and edge error (screen pixels), for one light.
std::vector<CheckFigure> accuracyFigures(const CheckLimits& limits, const std::string& subject,
                                         const AccuracyNumbers& numbers);
// The same for the whole picture of several lights: only the limits whose info says wholePicture (its edge error is
// only the largest light's, already judged per light).
std::vector<CheckFigure> wholePictureFigures(const CheckLimits& limits, const AccuracyNumbers& whole);

// The flicker figure (the largest over the motion's frame pairs) when a flicker limit is set; none otherwise.
std::vector<CheckFigure> flickerFigures(const CheckLimits& limits, const std::string& subject, double maxFlickerPercent);

// "acne 0.012 % (limit 0.100 %)" or "acne 12.345 % (limit 0.100 %: BROKEN)".
std::string describeFigure(const CheckFigure& figure);

}  // namespace shadowlab
