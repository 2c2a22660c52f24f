#include "settings/preset_catalog.h"

#include <algorithm>
#include <system_error>

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

std::vector<PresetEntry> presetsIn(const fs::path& folder, bool readOnly) {
    std::vector<PresetEntry> entries;
    std::error_code ec;
    if (folder.empty() || !fs::is_directory(folder, ec)) return entries;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path& path = it->path();
        if (path.extension() != ".json" || path.filename().string().front() == '.') continue;  // skip temporaries
        if (!it->is_regular_file(ec)) continue;
        entries.push_back({path.stem().string(), path, readOnly});
    }
    std::sort(entries.begin(), entries.end(), [](const PresetEntry& a, const PresetEntry& b) { return a.name < b.name; });
    return entries;
}

}  // namespace

std::vector<PresetEntry> listPresets(const fs::path& shippedDir, const fs::path& userDir) {
    std::vector<PresetEntry> all = presetsIn(shippedDir, true);
    // The same folder given twice (e.g. SHADOWLAB_USER_PRESETS pointing at presets/) is listed once, read-only.
    std::error_code ec;
    if (!userDir.empty() && !(fs::exists(shippedDir, ec) && fs::equivalent(shippedDir, userDir, ec))) {
        std::vector<PresetEntry> user = presetsIn(userDir, false);
        all.insert(all.end(), user.begin(), user.end());
    }
    return all;
}

std::optional<PresetEntry> findPreset(const std::string& nameOrPath, const fs::path& shippedDir,
                                      const fs::path& userDir) {
    std::error_code ec;
    if (!nameOrPath.empty() && fs::exists(nameOrPath, ec)) {
        const fs::path path(nameOrPath);
        const bool shipped = !shippedDir.empty() && fs::equivalent(path.parent_path().empty() ? "." : path.parent_path(),
                                                                   shippedDir, ec);
        return PresetEntry{path.stem().string(), path, shipped};
    }
    const std::string name = fs::path(nameOrPath).extension() == ".json" ? fs::path(nameOrPath).stem().string()
                                                                          : nameOrPath;
    if (name.empty() || name.find('/') != std::string::npos) return std::nullopt;
    for (const PresetEntry& entry : listPresets(shippedDir, userDir))  // shipped first
        if (entry.name == name) return entry;
    return std::nullopt;
}

}  // namespace shadowlab
