#include "accuracy/check_limits.h"

#include <cstdio>
#include <string>

namespace shadowlab {

namespace {

const CheckLimitInfo& info(std::optional<double> CheckLimits::*member) {
    for (const CheckLimitInfo& i : checkLimitInfos())
        if (i.member == member) return i;
    return checkLimitInfos().front();  // unreachable: every member is in the table
}

void add(std::vector<CheckFigure>& out, const CheckLimits& limits, std::optional<double> CheckLimits::*member,
         const std::string& subject, double value) {
    if (const std::optional<double>& max = limits.*member) out.push_back({subject, &info(member), value, *max});
}

}  // namespace

std::vector<CheckFigure> accuracyFigures(const CheckLimits& limits, const std::string& subject,
                                         const AccuracyNumbers& n) {
    std::vector<CheckFigure> out;
    add(out, limits, &CheckLimits::maxAcnePercent, subject, n.acnePercent);
    add(out, limits, &CheckLimits::maxLeakPercent, subject, n.leakPercent);
    add(out, limits, &CheckLimits::maxWrongPercent, subject, n.wrongPercent);
    add(out, limits, &CheckLimits::maxEdgePixels, subject, n.edgeErrorP95ScreenPixels);
    return out;
}

std::vector<CheckFigure> wholePictureFigures(const CheckLimits& limits, const AccuracyNumbers& whole) {
    std::vector<CheckFigure> out;
    for (CheckFigure& f : accuracyFigures(limits, "whole picture", whole))
        if (f.limit->wholePicture) out.push_back(std::move(f));
    return out;
}

std::vector<CheckFigure> flickerFigures(const CheckLimits& limits, const std::string& subject, double maxFlickerPercent) {
    std::vector<CheckFigure> out;
    add(out, limits, &CheckLimits::maxFlickerPercent, subject, maxFlickerPercent);
    return out;
}

std::string describeFigure(const CheckFigure& f) {
    // Percentages to 0.001 %, pixels to 0.01 px; a broken figure that would print as its limit gets more digits.
    auto format = [&](const char* pattern, double v) {
        char text[64];
        std::snprintf(text, sizeof text, pattern, v);
        return std::string(text);
    };
    const char* pattern = f.limit->percent ? "%.3f" : "%.2f";
    std::string value = format(pattern, f.value);
    const std::string max = format(pattern, f.max);
    if (f.broken() && value == max) value = format("%.9g", f.value);
    return std::string(f.limit->figure) + " " + value + " " + f.limit->unit + " (limit " + max + " " + f.limit->unit +
           (f.broken() ? ": BROKEN)" : ")");
}

}  // namespace shadowlab
