#pragma once
// Where the user's own files live (editor layout, recent files, user presets):
//   config folder:  $SHADOWLAB_CONFIG_DIR, else $XDG_CONFIG_HOME/shadowlab, else $HOME/.config/shadowlab
//   user presets:   $SHADOWLAB_USER_PRESETS, else <config folder>/presets
//   autosave:       <config folder>/autosave.json (the editor's unsaved settings, kept before crash-prone actions)
//   screenshots:    $SHADOWLAB_SCREENSHOTS, else $XDG_DATA_HOME/shadowlab/screenshots, else
//                   $HOME/.local/share/shadowlab/screenshots (created on the first screenshot)
// Empty variables count as unset. Nothing here creates folders.
#include <filesystem>

namespace shadowlab {

std::filesystem::path userConfigDir();
std::filesystem::path userPresetsDir();
std::filesystem::path recentFilesPath();  // <config folder>/recent-files.json
std::filesystem::path autosavePath();     // <config folder>/autosave.json
std::filesystem::path userScreenshotsDir();

// Creates `folder` (and its parents) if missing; "" or why it cannot be a writable folder.
std::string ensureFolder(const std::filesystem::path& folder);

}  // namespace shadowlab
