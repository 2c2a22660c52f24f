#include "editor/preset_session.h"

#include "settings/preset_io.h"

#include <filesystem>

namespace shadowlab::editor {

std::string presetNameFromPath(const std::string& path) { return std::filesystem::path(path).stem().string(); }

bool PresetSession::dirty(const Settings& settings) const {
    Settings compared = settings;
    compared.view = baseline_.view;
    return !(compared == baseline_);
}

void PresetSession::revert(Settings& settings) const {
    const ViewMode view = settings.view;
    settings = baseline_;
    settings.view = view;
}

std::string PresetSession::load(const std::string& path, bool shipped, Settings& settings) {
    PresetLoadResult loaded = loadPresetFile(path);
    if (!loaded.settings) {
        std::string why = loaded.errors.empty() ? path + ": could not be loaded" : loaded.errors.front();
        return why;
    }
    baseline_ = *loaded.settings;
    settings = baseline_;
    path_ = path;
    name_ = presetNameFromPath(path);
    shipped_ = shipped;
    scene_ = loaded.scene;
    return {};
}

std::string PresetSession::save(const Settings& settings, const std::string& scene) {
    if (path_.empty()) return "these settings have no preset file yet: use Save As";
    if (shipped_) return name_ + " is a shipped preset (read-only): use Save As to save a copy in your presets folder";
    if (fromPicture())
        return name_ + " is a screenshot's preset: use Save As to save it as a preset file";
    if (std::string error = savePresetFile(path_, settings, name_, {}, scene); !error.empty()) return error;
    baseline_ = settings;
    scene_ = scene;
    return {};
}

std::string PresetSession::saveAs(const std::string& path, const Settings& settings, bool overwrite,
                                  const std::string& scene) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!overwrite && fs::exists(path, ec)) return path + " already exists";
    const fs::path folder = fs::path(path).parent_path();
    if (!folder.empty()) {
        fs::create_directories(folder, ec);
        if (ec) return "cannot create " + folder.string() + ": " + ec.message();
    }
    const std::string name = presetNameFromPath(path);
    if (std::string error = savePresetFile(path, settings, name, {}, scene); !error.empty()) return error;
    baseline_ = settings;
    scene_ = scene;
    path_ = path;
    name_ = name;
    shipped_ = false;
    return {};
}

}  // namespace shadowlab::editor
