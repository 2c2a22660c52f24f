#include "accuracy/check_limits.h"

#include <cstdio>

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
                                         const AccuracyNumbers& n, bool withEdge) {
    std::vector<CheckFigure> out;
    add(out, limits, &CheckLimits::maxAcnePercent, subject, n.acnePercent);
    add(out, limits, &CheckLimits::maxLeakPercent, subject, n.leakPercent);
    add(out, limits, &CheckLimits::maxWrongPercent, subject, n.wrongPercent);
    if (withEdge) add(out, limits, &CheckLimits::maxEdgePixels, subject, n.edgeErrorP95ScreenPixels);
    return out;
}

std::vector<CheckFigure> flickerFigures(const CheckLimits& limits, const std::string& subject, double maxFlickerPercent) {
    std::vector<CheckFigure> out;
    add(out, limits, &CheckLimits::maxFlickerPercent, subject, maxFlickerPercent);
    return out;
}

std::string describeFigure(const CheckFigure& f) {
    const bool percent = f.limit->percent;
    char text[160];
    // Percentages to 0.001 %, pixels to 0.01 px: finer than any limit a case file sets.
    std::snprintf(text, sizeof text, percent ? "%s %.3f %s (limit %.3f %s%s)" : "%s %.2f %s (limit %.2f %s%s)",
                  f.limit->figure, f.value, f.limit->unit, f.max, f.limit->unit, f.broken() ? ": BROKEN" : "");
    return text;
}

}  // namespace shadowlab
