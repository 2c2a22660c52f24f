#pragma once
// The presets a user can pick: the shipped ones (read-only: saving one means "save as" into the user folder) and
// the user's own, each a *.json file; sorted by name, shipped first.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

struct PresetEntry {
    std::string name;             // the file name without .json
    std::filesystem::path path;
    bool readOnly = false;        // shipped with the tool
};

// Missing folders contribute nothing. A user preset named like a shipped one is listed too (as its own entry).
std::vector<PresetEntry> listPresets(const std::filesystem::path& shippedDir, const std::filesystem::path& userDir);

// What a --preset argument names, the same for the editor and every command: an existing file (read-only when it
// lies in the shipped folder), else a shipped preset's name, else a user preset's name ("NAME" or "NAME.json").
// nullopt when it is none of these.
std::optional<PresetEntry> findPreset(const std::string& nameOrPath, const std::filesystem::path& shippedDir,
                                      const std::filesystem::path& userDir);

}  // namespace shadowlab
