#pragma once
// Settings for a CLI command: a preset (a path, or the name of a shipped preset) plus --set key=value overrides,
// applied in order; every problem is reported with its key.
#include "settings/settings.h"

#include <optional>
#include <string>
#include <vector>

namespace shadowlab::cli {

// A path, else a shipped preset's name ("soft": <shipped data>/presets/soft.json, settings/shipped_data.h), else a
// user preset's name (settings/user_config.h), as the editor resolves it (findPreset); else the text unchanged, so
// the load names it.
std::string resolvePresetPath(const std::string& preset);

// nullopt after printing the errors to stderr; warnings go to stderr too. A preset tuned on another scene than
// `sceneSpec` gets an auto-framed camera there and a note on stderr (preset_scene.h); --set overrides come after.
// `where` (optional) starts every message and names the overrides "set" instead of "--set": settings read from a
// file (`check`'s "FILE: case 2 (\"name\")").
std::optional<Settings> settingsFromCli(const std::string& preset, const std::vector<std::string>& overrides,
                                        const std::string& sceneSpec = {}, const std::string& where = {});

}  // namespace shadowlab::cli
