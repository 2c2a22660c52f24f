#pragma once
// The editor's session kept before an action whose crash would lose work (a new shader variant or map allocation,
// a sweep, a scene load; issue 19): the unsaved settings as a preset file (it opens as one) with what the session
// needs to come back — the preset they were edited from and the scene. Written atomically; a clean exit or a save
// removes it, so one that exists at start is newer than the last clean exit and the editor offers to restore it.
#include "settings/settings.h"

#include <optional>
#include <string>

namespace shadowlab::editor {

struct Autosave {
    Settings settings;       // the unsaved settings
    std::string scene;       // the scene open then
    std::string presetPath;  // the preset they were edited from; "" = built-in defaults
    bool presetShipped = false;
    std::string savedAt;     // local time of writing, "YYYY-MM-DD HH:MM:SS" (filled by writeAutosave)
};

// Atomic (atomic_file.h); creates the folder. "" or why it failed, naming the file.
std::string writeAutosave(const std::string& path, Autosave autosave);

struct AutosaveRead {
    std::optional<Autosave> autosave;  // none when the file does not exist or cannot be read
    std::string error;                 // why an existing file cannot be read (named)
};
AutosaveRead readAutosave(const std::string& path);

// Removes the file if it exists; "" or why not.
std::string removeAutosave(const std::string& path);

}  // namespace shadowlab::editor
