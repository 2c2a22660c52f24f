#pragma once
// A cause's line in the editor's Causes tab and `measure`'s report: its share of each set it explains. Acne is a darkening of a lit
// pixel that is mostly not "wrong" (1-S < 0.5), so an acne cause is given as a share of acne, a leak cause as a share
// of leak, and a cause of wrong pixels as a share of wrong — never a share of a set its pixels are not in.
#include "accuracy/accuracy_meter.h"

#include <string>

namespace shadowlab {

// "99.6 % of acne, 0.4 % of wrong (12,345 px)"; a cause whose pixels are in none of the three sets (within k of a
// true edge, not wrong) is given as a share of the mismatched pixels within k.
std::string causeShares(const AccuracyReport& report, MismatchCause cause);

// 12,345
std::string groupedCount(std::size_t n);

}  // namespace shadowlab
