#include "accuracy/check_case.h"

#include "settings/json_text.h"
#include "settings/regular_file.h"
#include "settings/settings_fields.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace shadowlab {

using nlohmann::json;

const std::vector<CheckLimitInfo>& checkLimitInfos() {
    static const std::vector<CheckLimitInfo> infos = {
        {"maxAcnePercent", "--max-acne", "acne", "%", true, true, &CheckLimits::maxAcnePercent},
        {"maxLeakPercent", "--max-leak", "leak", "%", true, true, &CheckLimits::maxLeakPercent},
        {"maxWrongPercent", "--max-wrong", "wrong pixels", "%", true, true, &CheckLimits::maxWrongPercent},
        {"maxEdgePixels", "--max-edge-px", "edge error", "px", false, false, &CheckLimits::maxEdgePixels},
        {"maxFlickerPercent", "--max-flicker", "flicker", "%", true, false, &CheckLimits::maxFlickerPercent},
    };
    return infos;
}

std::string checkLimitValueError(const CheckLimitInfo& info, double value) {
    if (!std::isfinite(value)) return "not a finite number";
    if (value < 0.0) return "negative (a limit is at least 0)";
    if (info.percent && value > 100.0) return "more than 100 (a limit in percent is in [0, 100])";
    return {};
}

std::string defaultCheckCaseName(const CheckCase& c) {
    std::string name = c.scene + " " + (c.preset.empty() ? std::string("(defaults)") : c.preset);
    for (const std::string& o : c.overrides) name += " --set " + o;
    return name;
}

std::string checkCaseHasLimits(const CheckCase& c, const std::string& where) {
    for (const CheckLimitInfo& info : checkLimitInfos())
        if (c.limits.*info.member) return {};
    return where + ": no limit given, so nothing would be checked";
}

namespace {

const char* typeName(const json& v) {
    if (v.is_number()) return "a number";
    return v.type_name();  // "string", "boolean", "array", "object", "null"
}

// Parses one case; "" or the problem (the caller adds the file and case), naming the key.
std::string parseCase(const json& in, CheckCase& out) {
    if (!in.is_object()) return std::string("a case is an object with \"scene\" and limits, got ") + typeName(in);
    static const std::set<std::string> general = {"name", "scene", "preset", "set", "width", "height",
                                                  "motion", "step", "frames"};
    std::string known;
    for (const std::string& k : general) known += (known.empty() ? "" : ", ") + k;
    for (const CheckLimitInfo& info : checkLimitInfos()) known += std::string(", ") + info.key;
    for (const auto& [key, value] : in.items()) {
        const bool limit = std::any_of(checkLimitInfos().begin(), checkLimitInfos().end(),
                                       [&](const CheckLimitInfo& i) { return key == i.key; });
        if (!limit && !general.count(key))
            return "unknown key '" + describeKey(key) + "' (a case has " + known + ")";
    }
    auto string = [&](const char* key, std::string& to) -> std::string {
        if (!in.contains(key)) return {};
        const json& v = in[key];
        if (!v.is_string()) return std::string(key) + ": expected a string, got " + typeName(v);
        to = v.get<std::string>();
        if (to.empty()) return std::string(key) + ": empty";
        return {};
    };
    if (std::string e = string("scene", out.scene); !e.empty()) return e;
    if (out.scene.empty()) return "scene: missing (a .gltf/.glb path or builtin:NAME)";
    if (std::string e = string("preset", out.preset); !e.empty()) return e;
    if (std::string e = string("name", out.name); !e.empty()) return e;

    if (in.contains("set")) {
        const json& set = in["set"];
        if (set.is_array()) {
            for (std::size_t i = 0; i < set.size(); ++i) {
                if (!set[i].is_string())
                    return "set[" + std::to_string(i) + "]: expected \"key=value\", got " + typeName(set[i]);
                out.overrides.push_back(set[i].get<std::string>());
            }
        } else if (set.is_object()) {
            // A value is read as JSON by the override, so it is passed as JSON text: "pcf" stays a string.
            for (const auto& [key, value] : set.items()) {
                if (value.is_object() || value.is_null())
                    return "set." + describeKey(key) + ": expected a number, string, boolean or array, got " +
                           typeName(value);
                out.overrides.push_back(key + "=" + value.dump(-1, ' ', false, json::error_handler_t::replace));
            }
        } else {
            return std::string("set: expected a list of \"key=value\" or an object {key: value}, got ") + typeName(set);
        }
    }

    auto integer = [&](const char* key, int lo, int hi, int& to) -> std::string {
        if (!in.contains(key)) return {};
        const json& v = in[key];
        if (!v.is_number_integer() && !(v.is_number_float() && std::floor(v.get<double>()) == v.get<double>()))
            return std::string(key) + ": expected a whole number, got " + describeJsonValue(v);
        const double d = v.get<double>();
        if (d < lo || d > hi)
            return std::string(key) + ": " + describeJsonValue(v) + " is outside [" + std::to_string(lo) + ", " +
                   std::to_string(hi) + "]";
        to = int(d);
        return {};
    };
    if (std::string e = integer("width", 1, 16384, out.width); !e.empty()) return e;
    if (std::string e = integer("height", 1, 16384, out.height); !e.empty()) return e;

    for (const CheckLimitInfo& info : checkLimitInfos()) {
        if (!in.contains(info.key)) continue;
        const json& v = in[info.key];
        // NaN and infinities are not JSON; a string "nan" is refused as a string.
        if (!v.is_number()) return std::string(info.key) + ": expected a number, got " + typeName(v);
        const double d = v.get<double>();
        if (std::string e = checkLimitValueError(info, d); !e.empty())
            return std::string(info.key) + ": " + describeJsonValue(v) + " is " + e;
        out.limits.*info.member = d;
    }
    if (std::string e = checkCaseHasLimits(out, "limits"); !e.empty()) {
        std::string keys;
        for (const CheckLimitInfo& info : checkLimitInfos()) keys += (keys.empty() ? "" : ", ") + std::string(info.key);
        return e + " (give one of " + keys + ")";
    }

    const bool flicker = out.limits.maxFlickerPercent.has_value();
    for (const char* key : {"motion", "step", "frames"})
        if (in.contains(key) && !flicker)
            return std::string(key) + ": describes how flicker is measured, but the case has no maxFlickerPercent";
    if (in.contains("motion")) {
        std::string name;
        if (std::string e = string("motion", name); !e.empty()) return e;
        const std::optional<MotionKind> kind = parseMotion(name);
        if (!kind) return "motion: '" + describeKey(name) + "' is not a motion (" + motionNames() + ")";
        out.motion = *kind;
    }
    if (in.contains("step")) {
        const json& v = in["step"];
        if (!v.is_number()) return std::string("step: expected a number, got ") + typeName(v);
        out.step = v.get<double>();
    }
    if (std::string e = integer("frames", 2, kMaxMotionFrames, out.frames); !e.empty()) return e;
    if (out.name.empty()) out.name = defaultCheckCaseName(out);
    return {};
}

}  // namespace

std::optional<std::vector<CheckCase>> parseCheckCases(const std::string& text, const std::string& file,
                                                      std::string& error) {
    json doc;
    if (std::string e = parseJsonText(text, doc); !e.empty()) {
        error = file + ":" + e;
        return std::nullopt;
    }
    const char* shape = "a case file is {\"cases\": [{\"scene\": ..., \"maxAcnePercent\": ...}, ...]}";
    if (!doc.is_object()) {
        error = file + ": expected an object, got " + typeName(doc) + " (" + shape + ")";
        return std::nullopt;
    }
    for (const auto& [key, value] : doc.items())
        if (key != "cases") {
            error = file + ": unknown key '" + describeKey(key) + "' at the top (" + shape + ")";
            return std::nullopt;
        }
    if (!doc.contains("cases") || !doc["cases"].is_array()) {
        error = file + ": cases: " + (doc.contains("cases") ? std::string("expected a list, got ") + typeName(doc["cases"])
                                                              : std::string("missing")) + " (" + shape + ")";
        return std::nullopt;
    }
    const json& list = doc["cases"];
    if (list.empty()) {
        error = file + ": cases: the list is empty, so nothing would be checked";
        return std::nullopt;
    }
    std::vector<CheckCase> cases;
    std::set<std::string> names;
    for (std::size_t i = 0; i < list.size(); ++i) {
        CheckCase c;
        // The case as messages name it: its index from 1 and, once known, its name.
        std::string which = "case " + std::to_string(i + 1);
        if (list[i].is_object() && list[i].contains("name") && list[i]["name"].is_string())
            which += " (\"" + describeKey(list[i]["name"].get<std::string>()) + "\")";
        if (std::string e = parseCase(list[i], c); !e.empty()) {
            error = file + ": " + which + ": " + e;
            return std::nullopt;
        }
        if (!names.insert(c.name).second) {
            error = file + ": " + which + ": name: \"" + describeKey(c.name) +
                    "\" is used by an earlier case (each case needs its own name: the report and the JUnit file "
                    "tell them apart by it)";
            return std::nullopt;
        }
        cases.push_back(std::move(c));
    }
    return cases;
}

std::optional<std::vector<CheckCase>> loadCheckCases(const std::string& path, std::string& error) {
    std::string text;
    if (error = readRegularFile(path, kMaxCheckFileBytes, text); !error.empty()) return std::nullopt;
    return parseCheckCases(text, path, error);
}

}  // namespace shadowlab
