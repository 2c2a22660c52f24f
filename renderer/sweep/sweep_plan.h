#pragma once
// What a sweep will run: axes of preset keys, each with its values, and the points of their cartesian product —
// every value parsed and checked through the key table (settings_fields.h) before any work, so a bad key or value
// is refused with the key's own message. No GL.
#include "settings/settings.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

struct SweepAxis {
    std::string key;                  // a preset key, e.g. "shadow.resolution"
    std::vector<std::string> values;  // as the key table writes them back (e.g. "pcf", "1024", "[0,-1,0.2]")
};

struct SweepPoint {
    std::vector<std::string> values;  // one per axis, in axis order
    Settings settings;                // the base settings with these values applied
    std::string label() const;        // the values joined by spaces, e.g. "1024 pcf"
};

struct SweepPlan {
    std::string error;  // "" when every axis, value and combination is valid; else the first problem, naming the key
    std::vector<SweepAxis> axes;
    std::vector<SweepPoint> points;  // cartesian product, the first axis outermost
    // The base settings' own values for the axis keys (where the current preset sits on the axes).
    std::vector<std::string> baseValues;
    // The point whose values equal baseValues, or points.size() when the preset is not one of the points.
    std::size_t basePoint = 0;
};

// More points than this is refused (a typo such as a range pasted twice should not start an hours-long run).
inline constexpr std::size_t kMaxSweepPoints = 4096;

// `text` is "KEY=V1,V2,..." (commas inside [...] belong to a vector value). Refuses an unknown key (with the key
// table's suggestions), an axis given twice, an empty value, any value the key refuses, and any combination that
// Settings::validate() refuses — each naming the key.
SweepPlan planSweep(const Settings& base, const std::vector<std::string>& axisTexts);

// A value as the key table writes it back: strings without quotes, numbers in their shortest form.
std::string sweepValueText(const Settings& settings, const std::string& key);

}  // namespace shadowlab
