#pragma once
// `shadowlab check`'s cases: a scene, a preset with --set overrides, a view size and limits on what the accuracy
// meter measures (acne, leak, wrong pixels, edge error; flicker under a motion). A case list is a JSON file:
//   {"cases": [{"name": "textbook default", "scene": "builtin:textbook", "preset": "default",
//               "set": ["filter.kind=pcf", ...] or {"filter.kind": "pcf", "lights.0.direction": [0, -1, 0.2]},
//               "width": 320, "height": 180,
//               "maxAcnePercent": 0.1, "maxLeakPercent": 0.5, "maxWrongPercent": 1, "maxEdgePixels": 4,
//               "maxFlickerPercent": 0.1, "motion": "light", "step": 0.05, "frames": 4}, ...]}
// Only "scene" and at least one limit are required. Every problem names the file, the case (index from 1 and name)
// and the key. No GL.
#include "accuracy/motion.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

// The limits a case may set; absent ones are not checked (and flicker, absent, is not even measured).
struct CheckLimits {
    std::optional<double> maxAcnePercent;
    std::optional<double> maxLeakPercent;
    std::optional<double> maxWrongPercent;
    std::optional<double> maxEdgePixels;  // the 95th-percentile edge error in screen pixels
    std::optional<double> maxFlickerPercent;
};

// One limit: its case-file key, its command-line flag, the figure it bounds and that figure's unit. One table for
// the parser, the flags, the report and the JUnit file.
struct CheckLimitInfo {
    const char* key;     // "maxAcnePercent"
    const char* flag;    // "--max-acne"
    const char* figure;  // "acne"
    const char* unit;    // "%" or "px"
    bool percent;        // a percentage: at most 100
    bool wholePicture;   // also judged on the whole picture of several lights (edge error and flicker: per light only)
    std::optional<double> CheckLimits::*member;
};
const std::vector<CheckLimitInfo>& checkLimitInfos();

// "" when `value` can be a limit, else why ("not a finite number", "negative", "more than 100 %").
std::string checkLimitValueError(const CheckLimitInfo& info, double value);

inline constexpr int kCheckDefaultWidth = 640;
inline constexpr int kCheckDefaultHeight = 360;

struct CheckCase {
    std::string name;  // unique in its list; default: "SCENE PRESET [--set ...]"
    std::string scene;
    std::string preset;                  // "" = the built-in defaults
    std::vector<std::string> overrides;  // "key=value", applied in order as --set does
    int width = kCheckDefaultWidth;
    int height = kCheckDefaultHeight;
    CheckLimits limits;
    // How flicker is measured (only with limits.maxFlickerPercent): each casting light alone under this motion.
    MotionKind motion = MotionKind::Light;
    std::optional<double> step;  // default: motionInfo(motion).typicalStep
    int frames = kDefaultMotionFrames;
};

// The name a case gets when it has none.
std::string defaultCheckCaseName(const CheckCase& c);

// "" when at least one limit is set; else why, naming `where` (how the caller names its limits).
std::string checkCaseHasLimits(const CheckCase& c, const std::string& where);

// The cases of `text` (a case file's contents; `file` names it in messages), or nullopt with `error`.
std::optional<std::vector<CheckCase>> parseCheckCases(const std::string& text, const std::string& file,
                                                      std::string& error);

// As parseCheckCases, reading the regular file at `path` (at most kMaxCheckFileBytes).
inline constexpr std::size_t kMaxCheckFileBytes = 16u << 20;
std::optional<std::vector<CheckCase>> loadCheckCases(const std::string& path, std::string& error);

}  // namespace shadowlab
