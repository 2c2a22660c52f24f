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

bool PresetSession::sceneLoadFinished(bool ok, Settings& settings) {
    const bool discard = ok && discardOnSceneLoad_;
    discardOnSceneLoad_ = false;
    if (discard) revert(settings);
    return discard;
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

std::string presetNameProblem(const std::string& name) {
    if (name.empty()) return "enter a name";
    if (name.find_first_of("/\\") != std::string::npos) return "a name cannot contain / or \\";
    if (name.front() == '.') return "a name cannot start with a dot";
    return {};
}

std::string PresetSession::rename(const std::string& path) {
    namespace fs = std::filesystem;
    if (!canSaveInPlace()) return "only your own presets can be renamed (shipped presets and pictures are read-only)";
    std::error_code ec;
    if (fs::exists(path, ec)) return path + " already exists";
    fs::rename(path_, path, ec);  // same folder: atomic, nothing rewritten
    if (ec) return "cannot rename " + path_ + " to " + path + ": " + ec.message();
    path_ = path;
    name_ = presetNameFromPath(path);
    return {};
}

std::string PresetSession::remove(const std::string& deletedFolder) {
    namespace fs = std::filesystem;
    if (!canSaveInPlace()) return "only your own presets can be deleted (shipped presets and pictures are read-only)";
    std::error_code ec;
    fs::create_directories(deletedFolder, ec);
    if (ec) return "cannot create " + deletedFolder + ": " + ec.message();
    // Never overwrite an earlier deleted copy: name-1.json, name-2.json, ...
    fs::path target = fs::path(deletedFolder) / fs::path(path_).filename();
    for (int n = 1; fs::exists(target, ec); ++n)
        target = fs::path(deletedFolder) / (name_ + "-" + std::to_string(n) + ".json");
    fs::rename(path_, target, ec);
    if (ec) return "cannot move " + path_ + " to " + target.string() + ": " + ec.message();
    path_.clear();
    name_ = name_ + " (deleted)";
    return {};
}

}  // namespace shadowlab::editor
