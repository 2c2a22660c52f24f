#include "settings/user_config.h"

#include <cstdlib>
#include <string>
#include <system_error>

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

// The variable's value, or "" when unset or empty (an empty XDG_CONFIG_HOME means "use the default").
std::string environment(const char* name) {
    const char* value = std::getenv(name);
    return value ? std::string(value) : std::string();
}

}  // namespace

fs::path userConfigDir() {
    if (std::string dir = environment("SHADOWLAB_CONFIG_DIR"); !dir.empty()) return dir;
    if (std::string xdg = environment("XDG_CONFIG_HOME"); !xdg.empty()) return fs::path(xdg) / "shadowlab";
    if (std::string home = environment("HOME"); !home.empty()) return fs::path(home) / ".config" / "shadowlab";
    return fs::path(".shadowlab");  // no home at all (some CI sandboxes): beside the working directory
}

fs::path userPresetsDir() {
    if (std::string dir = environment("SHADOWLAB_USER_PRESETS"); !dir.empty()) return dir;
    return userConfigDir() / "presets";
}

fs::path recentFilesPath() { return userConfigDir() / "recent-files.json"; }

fs::path autosavePath() { return userConfigDir() / "autosave.json"; }

fs::path userScreenshotsDir() {
    if (std::string own = environment("SHADOWLAB_SCREENSHOTS"); !own.empty()) return fs::path(own);
    if (std::string xdg = environment("XDG_DATA_HOME"); !xdg.empty()) return fs::path(xdg) / "shadowlab" / "screenshots";
    if (std::string home = environment("HOME"); !home.empty())
        return fs::path(home) / ".local" / "share" / "shadowlab" / "screenshots";
    return fs::path("screenshots");  // no home at all: beside the working folder, as before
}

std::string ensureFolder(const fs::path& folder) {
    std::error_code ec;
    const fs::file_status status = fs::status(folder, ec);
    // A folder on the way that may not be searched: the path's type is unknown, not "a file" (the real cause).
    if (ec && status.type() != fs::file_type::not_found)
        return "cannot reach folder '" + folder.string() + "': " + ec.message();
    if (status.type() != fs::file_type::not_found) {
        if (fs::is_directory(status)) return {};
        std::string message = "'";  // appended, not "'" + ...: g++ 12 warns falsely there (-Wrestrict)
        message += folder.string();
        message += "' exists and is not a folder";
        return message;
    }
    fs::create_directories(folder, ec);
    if (ec) return "cannot create folder '" + folder.string() + "': " + ec.message();
    return {};
}

}  // namespace shadowlab
