// libFuzzer target: `shadowlab export` without GL. The input is a preset as for fuzz_preset (its text, then after a
// line "--set" one `--set key=value` per line); the settings are exported for builtin:textbook (the settings' own
// lights) and builtin:courtyard (its sun, two spots and point light when useSceneLights is on) in every format,
// the whole set and the last light alone.
// Whatever the settings, the export is refused with a message or every snippet is written: the JSON one parses, each
// light is listed with its shadow or the reason it has none, and --light beyond the set is refused by name.
#include "export/export_snippets.h"
#include "scene/builtin_scenes.h"
#include "scene/scene.h"
#include "fuzz_preset_input.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

using namespace shadowlab;

constexpr ExportFormat kFormats[] = {ExportFormat::D3D12, ExportFormat::D3D11, ExportFormat::Vulkan, ExportFormat::GL,
                                     ExportFormat::Json};

void writeEvery(const ShadowExportSet& set) {
    for (const LightExport& light : set.lights) {
        if (light.shadow.has_value() == !light.noShadowReason.empty()) __builtin_trap();  // one or the other
        if (light.shadow && light.shadow->views.size() != (light.type == LightType::Point ? 6u : 1u)) __builtin_trap();
    }
    // The set's text snippets hold each casting light's own snippet.
    for (ExportFormat format : kFormats) {
        const std::string text = exportSnippet(set, format);
        if (text.empty()) __builtin_trap();
        if (format != ExportFormat::Json) continue;
        const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
        if (j.is_discarded() || !j.contains("lights") || j["lights"].size() != set.lights.size()) __builtin_trap();
    }
}

void exportFor(const Settings& settings, const Scene& scene, const std::string& label) {
    std::string error;
    const std::optional<ShadowExportSet> set = exportForScene(settings, scene, label, std::nullopt, error);
    if (!set) {
        if (error.empty()) __builtin_trap();  // a refusal always says why
        return;
    }
    if (set->lights.size() != set->lightCount) __builtin_trap();
    writeEvery(*set);
    if (set->lightCount > 0) {
        const std::optional<ShadowExportSet> last = exportForScene(settings, scene, label, set->lightCount - 1, error);
        if (!last || last->lights.size() != 1) __builtin_trap();
        writeEvery(*last);
    }
    error.clear();
    if (exportForScene(settings, scene, label, set->lightCount, error) || error.empty()) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const Scene textbook = *makeBuiltinScene("textbook");
    static const Scene courtyard = *makeBuiltinScene("courtyard");
    const Settings settings =
        fuzz::parsePresetInput(std::string_view(reinterpret_cast<const char*>(data), size)).settings;
    exportFor(settings, textbook, "builtin:textbook");
    exportFor(settings, courtyard, "builtin:courtyard");
    return 0;
}
