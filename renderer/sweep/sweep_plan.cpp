#include "sweep/sweep_plan.h"

#include "settings/settings_fields.h"

#include <algorithm>

namespace shadowlab {

namespace {

// Splits on commas outside brackets and quotes: "512,[0,-1,0.2]" -> "512", "[0,-1,0.2]".
std::vector<std::string> splitValues(std::string_view text) {
    std::vector<std::string> values;
    std::string current;
    int depth = 0;
    bool quoted = false;
    for (char c : text) {
        if (c == '"') quoted = !quoted;
        if (!quoted && (c == '[' || c == '{')) ++depth;
        if (!quoted && (c == ']' || c == '}')) --depth;
        if (c == ',' && depth <= 0 && !quoted) {
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
        // Unknown keys get the key table's own message (with its suggestions).
        if (!findSettingsField(axis.key)) {
            Settings scratch = base;
            return refuse("--axis: " + applySettingOverride(scratch, axis.key + "=0"));
        }
        if (std::any_of(plan.axes.begin(), plan.axes.end(), [&](const SweepAxis& a) { return a.key == axis.key; }))
            return refuse("--axis " + axis.key + ": this key is already an axis");
        for (const std::string& raw : splitValues(std::string_view(text).substr(eq + 1))) {
            const std::string value = trimmed(raw);
            if (value.empty()) return refuse("--axis " + axis.key + ": an empty value in '" + describeKey(text) + "'");
            Settings settings = base;
            if (std::string error = applySettingOverride(settings, axis.key + "=" + value); !error.empty())
                return refuse("--axis " + axis.key + ": " + error);
            const std::string canonical = sweepValueText(settings, axis.key);
            if (std::find(axis.values.begin(), axis.values.end(), canonical) != axis.values.end())
                return refuse("--axis " + axis.key + ": the value " + canonical + " is given twice");
            axis.values.push_back(canonical);
        }
        count *= axis.values.size();
        if (count > kMaxSweepPoints)
            return refuse("--axis: the axes make more than " + std::to_string(kMaxSweepPoints) + " points");
        plan.baseValues.push_back(sweepValueText(base, axis.key));
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
            applySettingOverride(point.settings, plan.axes[a].key + "=" + value);
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
