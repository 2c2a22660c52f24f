#include "cli/settings_from_cli.h"

#include "settings/preset_catalog.h"
#include "settings/preset_io.h"
#include "settings/preset_scene.h"
#include "settings/settings_fields.h"
#include "settings/shipped_data.h"
#include "settings/user_config.h"

#include <filesystem>
#include <iostream>

namespace shadowlab::cli {

std::string resolvePresetPath(const std::string& preset) {
    const std::filesystem::path shipped = shippedPresetsDir();
    if (std::optional<PresetEntry> found = findPreset(preset, shipped, userPresetsDir())) return found->path.string();
    // The load below says "no such file"; this says why a shipped name was not found either.
    if (shipped.empty()) std::cerr << "note: --preset " << preset << ": " << shippedData().problem << "\n";
    return preset;
}

std::optional<Settings> settingsFromCli(const std::string& preset, const std::vector<std::string>& overrides,
                                        const std::string& sceneSpec, const std::string& where) {
    const std::string at = where.empty() ? std::string() : where + ": ";
    const char* setLabel = where.empty() ? "--set " : "set ";
    Settings settings;
    if (!preset.empty()) {
        PresetLoadResult loaded = loadPresetFile(resolvePresetPath(preset));
        for (const std::string& w : loaded.warnings) std::cerr << "warning: " << at << w << "\n";
        if (!loaded.settings) {
            for (const std::string& e : loaded.errors) std::cerr << "error: " << at << e << "\n";
            return std::nullopt;
        }
        settings = *loaded.settings;
        if (!sceneSpec.empty())
            if (std::string note = adaptPresetToScene(settings, loaded.scene, sceneSpec); !note.empty())
                std::cerr << "note: " << at << note << "\n";
    }
    bool ok = true;
    for (const std::string& kv : overrides) {
        if (std::string error = applySettingOverride(settings, kv); !error.empty()) {
            std::cerr << "error: " << at << setLabel << describeKey(kv) << ": " << error << "\n";
            ok = false;
        }
    }
    if (!ok) return std::nullopt;
    if (std::vector<std::string> problems = settings.validate(); !problems.empty()) {
        for (const std::string& p : problems) std::cerr << "error: " << at << p << "\n";
        return std::nullopt;
    }
    return settings;
}

}  // namespace shadowlab::cli
