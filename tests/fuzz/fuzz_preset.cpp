// libFuzzer target: a preset's text, then (after a line "--set") one `--set key=value` per line. Whatever the bytes,
// loading ends in settings or in messages; a loaded preset saves and loads back.
#include "settings/preset_io.h"
#include "settings/settings_fields.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace shadowlab;
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    constexpr std::string_view separator = "\n--set\n";
    const std::size_t split = input.find(separator);
    const std::string text(input.substr(0, split));

    PresetLoadResult r = presetFromText(text);
    Settings settings = r.settings.value_or(Settings{});
    if (split != std::string_view::npos) {
        std::string_view rest = input.substr(split + separator.size());
        while (!rest.empty()) {
            const std::size_t end = rest.find('\n');
            (void)applySettingOverride(settings, rest.substr(0, end));
            rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
        }
    }
    for (const std::string& problem : settings.validate()) (void)problem;
    if (r.settings) {
        // What was accepted must save and load back: a preset the tool writes is one it can read.
        const PresetLoadResult back = presetFromText(presetToText(*r.settings, r.name, r.description));
        if (!back.settings) __builtin_trap();
    }
    return 0;
}
