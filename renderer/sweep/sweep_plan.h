#pragma once
// What a sweep will run: axes of preset keys, each with its values, and the points of their cartesian product —
// every value parsed and checked through the key table (settings_fields.h) before any work, so a bad key or value
// is refused with the key's own message. No GL.
#include "settings/settings.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace shadowlab {

// One axis: a preset key, or several moving together ("filter.kind,filter.kernel" with values "pcf:3", "pcf:9",
// "point:1"), for choices that are one idea in two keys.
struct SweepAxis {
    std::string key;                  // as given: "shadow.resolution", or the keys joined by ',' for a joint axis
    std::vector<std::string> keys;    // the preset keys it sets (one, or several for a joint axis)
    std::vector<std::string> values;  // as the key table writes them back (e.g. "pcf", "1024", "[0,-1,0.2]"),
                                      // a joint axis's parts joined by ':' ("pcf:3")
};

// The (key, value) assignments of one of the axis's values, in key order ("pcf:3" -> filter.kind=pcf,
// filter.kernel=3); empty when the value has not one part per key.
std::vector<std::pair<std::string, std::string>> axisAssignments(const SweepAxis& axis, const std::string& value);

// Where these settings sit on the axis: its value text as the plan writes it (joint parts joined by ':').
std::string axisValueText(const Settings& settings, const SweepAxis& axis);

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

// `text` is "KEY=V1,V2,..." (commas inside [...] belong to a vector value), or "KEY1,KEY2=A1:B1,A2:B2,..." for a
// joint axis. Refuses an unknown key (with the key
// table's suggestions), an axis given twice, an empty value, any value the key refuses, and any combination that
// Settings::validate() refuses — each naming the key.
SweepPlan planSweep(const Settings& base, const std::vector<std::string>& axisTexts);

// A value as the key table writes it back: strings without quotes, numbers in their shortest form.
std::string sweepValueText(const Settings& settings, const std::string& key);

}  // namespace shadowlab
