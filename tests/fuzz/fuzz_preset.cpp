// libFuzzer target: a preset's text, then (after a line "--set") one `--set key=value` per line. Whatever the bytes,
// loading ends in settings or in messages; a loaded preset saves and loads back.
#include "fuzz_preset_input.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace shadowlab;
    const fuzz::PresetInput input = fuzz::parsePresetInput(std::string_view(reinterpret_cast<const char*>(data), size));
    const PresetLoadResult& r = input.loaded;
    for (const std::string& problem : input.settings.validate()) (void)problem;
    if (r.settings) {
        // What was accepted must save and load back: a preset the tool writes is one it can read.
        const PresetLoadResult back = presetFromText(presetToText(*r.settings, r.name, r.description));
        if (!back.settings) __builtin_trap();
    }
    return 0;
}
