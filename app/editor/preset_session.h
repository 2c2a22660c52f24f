#pragma once
// Which preset the editor's settings came from, and whether they changed since: shipped presets are read-only
// (saving one asks for a new name in the user folder), user presets are saved in place, atomically.
#include "settings/settings.h"

#include <string>

namespace shadowlab::editor {

class PresetSession {
public:
    // Starts from built-in defaults, named "default" but not backed by a file: Save asks for a name.
    explicit PresetSession(Settings baseline = {}) : baseline_(std::move(baseline)) {}

    // Loads a preset file. On error returns why and leaves the session and `settings` untouched.
    std::string load(const std::string& path, bool shipped, Settings& settings);
    // Saves to the current file, recording `scene` as the one it was tuned on. Refused (with a reason) for shipped
    // presets and unnamed sessions: use saveAs.
    std::string save(const Settings& settings, const std::string& scene);
    // Saves to `path` (refuses to replace an existing file unless `overwrite`) and makes it the current preset.
    std::string saveAs(const std::string& path, const Settings& settings, bool overwrite, const std::string& scene);
    // User presets only (canSaveInPlace): renames the file to `path` in the same folder (refused if that exists), the
    // content untouched; or moves it into `deletedFolder` (recoverable, never erased), after which the session is
    // unnamed (Save asks for a name) and the settings stay as they are.
    std::string rename(const std::string& path);
    std::string remove(const std::string& deletedFolder);
    // Back to the settings as last loaded or saved; the view mode stays as the user chose it (see dirty()).
    void revert(Settings& settings) const;

    // "Don't save" before a scene load: the edits are declined, but a load can fail, so they go only once the new
    // scene has loaded (sceneLoadFinished(true)); a failed load keeps them, still unsaved.
    void discardEditsOnSceneLoad() { discardOnSceneLoad_ = true; }
    // The scene load ended: on success the declined edits are replaced by the preset as saved (true when they
    // were); either way the request is settled.
    bool sceneLoadFinished(bool ok, Settings& settings);

    // The view mode (lit / shadow / light depth) is how the user looks, not what they tuned: switching it never marks
    // the preset as changed. A save still writes it (the CLI renders the preset's `view`).
    bool dirty(const Settings& settings) const;
    // A screenshot (.png carrying a preset) is never rewritten as JSON: Save As.
    bool canSaveInPlace() const { return !path_.empty() && !shipped_ && !fromPicture(); }
    const std::string& path() const { return path_; }
    const std::string& name() const { return name_; }
    bool shipped() const { return shipped_; }
    bool fromPicture() const { return path_.ends_with(".png"); }  // loaded from a screenshot's text chunk
    const Settings& baseline() const { return baseline_; }
    const std::string& scene() const { return scene_; }  // the scene it was tuned on; "" when it records none

private:
    Settings baseline_;         // the settings as last loaded or saved
    std::string path_;          // empty: not backed by a file
    std::string name_ = "built-in defaults";
    bool shipped_ = false;
    std::string scene_;
    bool discardOnSceneLoad_ = false;
};

// "acne" for ".../presets/acne.json".
std::string presetNameFromPath(const std::string& path);

// "" when `name` can name a preset file in the user folder, else what is wrong with it.
std::string presetNameProblem(const std::string& name);

}  // namespace shadowlab::editor
