#include "accuracy/cause_shares.h"

#include <cstdio>

namespace shadowlab {

std::string groupedCount(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string causeShares(const AccuracyReport& report, MismatchCause cause) {
    const AccuracyCounts& c = report.counts;
    const std::size_t i = std::size_t(cause);
    std::string text;
    auto add = [&](std::size_t pixels, double percent, const char* set) {
        if (pixels == 0) return;
        char part[64];
        std::snprintf(part, sizeof part, "%s%.1f %% of %s", text.empty() ? "" : ", ", percent, set);
        text += part;
    };
    add(c.causeAcne[i], report.causePercentOfAcne(cause), "acne");
    add(c.causeLeak[i], report.causePercentOfLeak(cause), "leak");
    add(c.causeWrong[i], report.causePercentOfWrong(cause), "wrong");
    if (text.empty()) {
        char part[64];
        std::snprintf(part, sizeof part, "%.1f %% of the mismatched within k",
                      c.mismatchedWithinK ? 100.0 * double(c.causePixels[i]) / double(c.mismatchedWithinK) : 0.0);
        text = part;
    }
    return text + " (" + groupedCount(c.causePixels[i]) + " px)";
}

}  // namespace shadowlab
