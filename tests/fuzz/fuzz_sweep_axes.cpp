// libFuzzer target: `sweep --axis` planning. The input is a preset's text, a line "--axis", then one axis text per
// line ("KEY=V1,V2,..." or "KEY1,KEY2=A1:B1,..."); without the "--axis" line every line is an axis and the base is
// the default settings. Whatever the bytes, the plan is refused with a message or it keeps its promises: at most
// kMaxSweepPoints points, every point valid, one value per axis, no setting on two axes (aliases resolved), and each
// point's settings read back the values its label names.
#include "settings/preset_io.h"
#include "settings/settings_fields.h"
#include "sweep/sweep_plan.h"

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace shadowlab;
    std::string_view input(reinterpret_cast<const char*>(data), size);
    constexpr std::string_view separator = "\n--axis\n";
    Settings base;
    if (const std::size_t split = input.find(separator); split != std::string_view::npos) {
        const PresetLoadResult preset = presetFromText(std::string(input.substr(0, split)));
        if (preset.settings) base = *preset.settings;
        input = input.substr(split + separator.size());
    }
    std::vector<std::string> axes;
    while (!input.empty()) {
        const std::size_t end = input.find('\n');
        axes.emplace_back(input.substr(0, end));
        input = end == std::string_view::npos ? std::string_view{} : input.substr(end + 1);
    }

    const SweepPlan plan = planSweep(base, axes);
    if (!plan.error.empty()) {
        if (!plan.points.empty()) __builtin_trap();  // a refused plan runs nothing
        return 0;
    }
    if (plan.points.empty() || plan.points.size() > kMaxSweepPoints) __builtin_trap();
    if (plan.baseValues.size() != plan.axes.size()) __builtin_trap();
    std::set<std::string> keys;
    for (const SweepAxis& axis : plan.axes) {
        if (axis.keys.empty() || axis.values.empty()) __builtin_trap();
        for (const std::string& key : axis.keys) {
            const SettingsField* field = findSettingsField(key);
            // Axes carry canonical keys (an alias is resolved to the key it stands for), each once.
            if (!field || !field->aliasOf.empty() || !keys.insert(key).second) __builtin_trap();
        }
    }
    for (const SweepPoint& point : plan.points) {
        if (point.values.size() != plan.axes.size() || !point.settings.validate().empty()) __builtin_trap();
        for (std::size_t a = 0; a < plan.axes.size(); ++a)
            if (axisValueText(point.settings, plan.axes[a]) != point.values[a]) __builtin_trap();
    }
    if (plan.basePoint > plan.points.size()) __builtin_trap();
    return 0;
}
