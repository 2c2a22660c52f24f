#include "editor/autosave.h"

#include "editor/message_log.h"
#include "settings/atomic_file.h"
#include "settings/preset_io.h"
#include "settings/regular_file.h"
#include "settings/user_config.h"

#include <nlohmann/json.hpp>

#include <ctime>
#include <filesystem>

namespace shadowlab::editor {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSessionKey = "autosave";  // the preset's extra group (presets ignore unknown keys)

}  // namespace

std::string writeAutosave(const std::string& path, Autosave autosave) {
    if (std::string error = ensureFolder(fs::path(path).parent_path()); !error.empty())
        return "autosave " + path + ": " + error;
    autosave.savedAt = localTimeText("%Y-%m-%d %H:%M:%S");
    nlohmann::json json = presetToJson(autosave.settings, "autosave", "unsaved settings kept by the editor",
                                       autosave.scene);
    json[kSessionKey] = {{"presetPath", autosave.presetPath},
                         {"presetShipped", autosave.presetShipped},
                         {"savedAt", autosave.savedAt}};
    if (std::string error = writeFileAtomically(path, json.dump(2) + "\n"); !error.empty())
        return "autosave " + path + ": " + error;
    return {};
}

AutosaveRead readAutosave(const std::string& path) {
    AutosaveRead out;
    std::error_code ec;
    if (!fs::exists(path, ec)) return out;
    std::string text;
    if (std::string error = readRegularFile(path, kMaxPresetBytes, text); !error.empty()) {
        out.error = "autosave " + error;
        return out;
    }
    // The preset reader first: it bounds the nesting and checks every setting.
    PresetLoadResult preset = presetFromText(text);
    if (!preset.settings) {
        out.error = "autosave " + path + ": " + (preset.errors.empty() ? "unreadable" : preset.errors.front());
        return out;
    }
    const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    const nlohmann::json session = json.is_object() && json.contains(kSessionKey) ? json[kSessionKey] : nlohmann::json();
    if (!session.is_object() || !session.value("presetPath", nlohmann::json()).is_string() ||
        !session.value("presetShipped", nlohmann::json()).is_boolean()) {
        out.error = "autosave " + path + ": no \"" + kSessionKey + "\" group with presetPath and presetShipped";
        return out;
    }
    Autosave a;
    a.settings = *preset.settings;
    a.scene = preset.scene;
    a.presetPath = session["presetPath"].get<std::string>();
    a.presetShipped = session["presetShipped"].get<bool>();
    if (session.contains("savedAt") && session["savedAt"].is_string()) a.savedAt = session["savedAt"].get<std::string>();
    out.autosave = std::move(a);
    return out;
}

std::string removeAutosave(const std::string& path) {
    std::error_code ec;
    fs::remove(path, ec);
    if (ec) return "autosave " + path + ": cannot remove it: " + ec.message();
    return {};
}

}  // namespace shadowlab::editor
