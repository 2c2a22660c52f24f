#pragma once
// The input format of the preset-driven fuzz targets (fuzz_preset, fuzz_export): a preset's text, then (after a line
// "--set") one `--set key=value` per line, applied over what loaded (or over the defaults when the text is refused).
#include "settings/preset_io.h"
#include "settings/settings_fields.h"

#include <string>
#include <string_view>

namespace shadowlab::fuzz {

struct PresetInput {
    PresetLoadResult loaded;  // the preset text alone
    Settings settings;        // loaded (or the defaults), then every --set line that applies
};

inline PresetInput parsePresetInput(std::string_view input) {
    constexpr std::string_view separator = "\n--set\n";
    const std::size_t split = input.find(separator);
    PresetInput p;
    p.loaded = presetFromText(std::string(input.substr(0, split)));
    p.settings = p.loaded.settings.value_or(Settings{});
    if (split != std::string_view::npos) {
        std::string_view rest = input.substr(split + separator.size());
        while (!rest.empty()) {
            const std::size_t end = rest.find('\n');
            (void)applySettingOverride(p.settings, rest.substr(0, end));
            rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
        }
    }
    return p;
}

}  // namespace shadowlab::fuzz
