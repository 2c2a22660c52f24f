#include "sweep/sweep_plan.h"

#include "settings/settings_fields.h"

#include <algorithm>

namespace shadowlab {

namespace {

// Splits on a separator outside brackets and quotes: "512,[0,-1,0.2]" -> "512", "[0,-1,0.2]".
std::vector<std::string> splitValues(std::string_view text, char separator = ',') {
    std::vector<std::string> values;
    std::string current;
    int depth = 0;
    bool quoted = false;
    for (char c : text) {
        if (c == '"') quoted = !quoted;
        if (!quoted && (c == '[' || c == '{')) ++depth;
        if (!quoted && (c == ']' || c == '}')) --depth;
        if (c == separator && depth <= 0 && !quoted) {
            values.push_back(current);
            current.clear();
        } else {
            current += c;
        }
    }
    values.push_back(current);
    return values;
}

std::string trimmed(std::string_view s) {
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string_view::npos) return {};
    return std::string(s.substr(first, s.find_last_not_of(" \t") - first + 1));
}

}  // namespace

std::string SweepPoint::label() const {
    std::string text;
    for (const std::string& v : values) text += (text.empty() ? "" : " ") + v;
    return text;
}

std::string sweepValueText(const Settings& settings, const std::string& key) {
    const SettingsField* field = findSettingsField(key);
    if (!field) return "";
    const nlohmann::json value = field->get(settings);
    return value.is_string() ? value.get<std::string>() : value.dump();
}

std::vector<std::pair<std::string, std::string>> axisAssignments(const SweepAxis& axis, const std::string& value) {
    const std::vector<std::string> parts =
        axis.keys.size() == 1 ? std::vector<std::string>{value} : splitValues(value, ':');
    if (parts.size() != axis.keys.size()) return {};
    std::vector<std::pair<std::string, std::string>> assignments;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const std::string part = trimmed(parts[k]);
        if (part.empty()) return {};
        assignments.emplace_back(axis.keys[k], part);
    }
    return assignments;
}

std::string axisValueText(const Settings& settings, const SweepAxis& axis) {
    std::string text;
    for (const std::string& key : axis.keys) {
        if (!text.empty()) text += ':';
        text += sweepValueText(settings, key);
    }
    return text;
}

SweepPlan planSweep(const Settings& base, const std::vector<std::string>& axisTexts) {
    SweepPlan plan;
    auto refuse = [&](std::string error) {
        plan.error = std::move(error);
        plan.points.clear();
        return plan;
    };
    if (axisTexts.empty()) return refuse("--axis: give at least one axis, e.g. --axis shadow.resolution=512,1024,2048");
    std::size_t count = 1;
    for (const std::string& text : axisTexts) {
        const auto eq = text.find('=');
        if (eq == std::string::npos)
            return refuse("--axis expects KEY=V1,V2,..., got '" + describeKey(text) + "'");
        SweepAxis axis;
        axis.key = trimmed(std::string_view(text).substr(0, eq));
        for (const std::string& part : splitValues(axis.key)) {
            const std::string typed = trimmed(part);
            // Unknown keys get the key table's own message (with its suggestions).
            const SettingsField* field = findSettingsField(typed);
            if (!field) {
                Settings scratch = base;
                return refuse("--axis: " + applySettingOverride(scratch, typed + "=0"));
            }
            // A schema-1 alias is the key it stands for: one setting, one axis, one label, whichever way it is typed.
            const std::string key = field->aliasOf.empty() ? typed : field->aliasOf;
            for (const SweepAxis& other : plan.axes)
                if (std::find(other.keys.begin(), other.keys.end(), key) != other.keys.end())
                    return refuse("--axis " + key + ": this key is already an axis");
            if (std::find(axis.keys.begin(), axis.keys.end(), key) != axis.keys.end())
                return refuse("--axis " + key + ": this key is given twice in one axis");
            axis.keys.push_back(key);
        }
        axis.key.clear();
        for (const std::string& key : axis.keys) axis.key += (axis.key.empty() ? "" : ",") + key;
        for (const std::string& raw : splitValues(std::string_view(text).substr(eq + 1))) {
            const std::string value = trimmed(raw);
            if (value.empty()) return refuse("--axis " + axis.key + ": an empty value in '" + describeKey(text) + "'");
            const auto parts = axisAssignments(axis, value);
            if (parts.empty())
                return refuse("--axis " + axis.key + ": '" + describeKey(value) + "' needs " +
                              std::to_string(axis.keys.size()) + " parts separated by ':', one per key");
            Settings settings = base;
            for (const auto& [key, part] : parts)
                if (std::string error = applySettingOverride(settings, key + "=" + part); !error.empty())
                    return refuse("--axis " + key + ": " + error);
            const std::string canonical = axisValueText(settings, axis);
            if (std::find(axis.values.begin(), axis.values.end(), canonical) != axis.values.end())
                return refuse("--axis " + axis.key + ": the value " + canonical + " is given twice");
            axis.values.push_back(canonical);
        }
        count *= axis.values.size();
        if (count > kMaxSweepPoints)
            return refuse("--axis: the axes make more than " + std::to_string(kMaxSweepPoints) + " points");
        plan.baseValues.push_back(axisValueText(base, axis));
        plan.axes.push_back(std::move(axis));
    }

    // The cartesian product, the last axis fastest.
    std::vector<std::size_t> index(plan.axes.size(), 0);
    for (std::size_t n = 0; n < count; ++n) {
        SweepPoint point;
        point.settings = base;
        for (std::size_t a = 0; a < plan.axes.size(); ++a) {
            const std::string& value = plan.axes[a].values[index[a]];
            point.values.push_back(value);
            // Checked above; the canonical text reads back to the same value.
            for (const auto& [key, part] : axisAssignments(plan.axes[a], value))
                applySettingOverride(point.settings, key + "=" + part);
        }
        if (std::vector<std::string> problems = point.settings.validate(); !problems.empty())
            return refuse("--axis point " + point.label() + ": " + problems.front());
        plan.points.push_back(std::move(point));
        for (std::size_t a = plan.axes.size(); a-- > 0;) {
            if (++index[a] < plan.axes[a].values.size()) break;
            index[a] = 0;
        }
    }
    plan.basePoint = plan.points.size();
    for (std::size_t i = 0; i < plan.points.size(); ++i)
        if (plan.points[i].values == plan.baseValues) plan.basePoint = i;
    return plan;
}

}  // namespace shadowlab
