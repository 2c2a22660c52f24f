#pragma once
// Values a test can give any key of the table: the ones the key accepts that differ from `current` (its range's ends
// and middle, every choice, a flipped flag), so a test can walk the table without knowing its keys.
#include "settings/settings_fields.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace shadowlab::test {

inline std::vector<nlohmann::json> otherValues(const SettingsField& f, const nlohmann::json& current) {
    std::vector<nlohmann::json> values;
    switch (f.kind) {
        case SettingsFieldKind::Bool: values = {true, false}; break;
        case SettingsFieldKind::Enum: for (const std::string& c : f.choices) values.push_back(c); break;
        case SettingsFieldKind::Int:
            if (!f.intChoices.empty()) for (int c : f.intChoices) values.push_back(c);
            else values = {int(f.min), 512, int(f.min + (f.max - f.min) / 2), int(f.max)};
            break;
        case SettingsFieldKind::Float:
            values = {f.min, f.max, double(float(f.min + (f.max - f.min) * 0.0318309886)), (f.min + f.max) / 2};
            // A light's size is a directional light's angle too (at most 90 degrees): sizes every type accepts.
            if (f.name() == "size") values = {f.min, 0.5, 2.0, 45.0};
            break;
        case SettingsFieldKind::Vec3:
            values = {nlohmann::json::array({0.25, -2.25, 0.125}), nlohmann::json::array({0.5, 0.5, 0.5}),
                      nlohmann::json::array({1.0, 2.0, 3.0})};
            break;
        case SettingsFieldKind::StringList: values = {nlohmann::json::array({"a node the scene lacks"})}; break;
        case SettingsFieldKind::String: values = {"none", "0", "a name the scene lacks"}; break;
    }
    std::vector<nlohmann::json> other;
    for (const nlohmann::json& v : values)
        if (v != current) other.push_back(v);
    return other;
}

}  // namespace shadowlab::test
