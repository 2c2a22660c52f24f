#include "settings/recent_files.h"

#include "settings/regular_file.h"

#include "settings/atomic_file.h"
#include "settings/user_config.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace shadowlab {

namespace fs = std::filesystem;

std::string normalizedSceneSpec(const std::string& spec) {
    if (spec.rfind("builtin:", 0) == 0) return spec;
    std::error_code ec;
    fs::path absolute = fs::absolute(fs::path(spec), ec);
    if (ec) return spec;
    return absolute.lexically_normal().string();
}

void RecentFiles::add(const std::string& spec) {
    if (spec.empty()) return;
    const std::string normalized = normalizedSceneSpec(spec);
    remove(normalized);
    items_.insert(items_.begin(), normalized);
    if (items_.size() > kMaxRecentFiles) items_.resize(kMaxRecentFiles);
}

void RecentFiles::remove(const std::string& spec) {
    const std::string normalized = normalizedSceneSpec(spec);
    items_.erase(std::remove(items_.begin(), items_.end(), normalized), items_.end());
}

RecentFilesLoad loadRecentFiles(const fs::path& file) {
    RecentFilesLoad out;
    std::error_code ec;
    if (!fs::exists(file, ec)) return out;
    const std::string name = file.string();
    std::string text;
    // A list of ten paths: 1 MiB is generous, and a FIFO or device put in its place is refused, not read.
    if (std::string error = readRegularFile(name, 1u << 20, text); !error.empty()) {
        out.error = std::move(error);
        return out;
    }
    const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (json.is_discarded()) {
        out.error = name + ": not valid JSON";
        return out;
    }
    if (!json.is_object() || !json.contains("recentFiles") || !json["recentFiles"].is_array()) {
        out.error = name + ": expected {\"recentFiles\": [...]}";
        return out;
    }
    // Stored most recent first: add in reverse so the order survives (and duplicates or extras are dropped).
    const nlohmann::json& list = json["recentFiles"];
    for (auto it = list.rbegin(); it != list.rend(); ++it)
        if (it->is_string()) out.files.add(it->get<std::string>());
    return out;
}

std::string saveRecentFiles(const fs::path& file, const RecentFiles& files) {
    const std::string failed = "cannot save the recent files list '" + file.string() + "': ";
    if (std::string error = ensureFolder(file.parent_path().empty() ? fs::path(".") : file.parent_path());
        !error.empty())
        return failed + error;
    const nlohmann::json json = {{"recentFiles", files.items()}};
    // replace: a path that is not UTF-8 is saved with U+FFFD rather than throwing.
    const std::string text = json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    if (std::string error = writeFileAtomically(file.string(), text); !error.empty()) return failed + error;
    return {};
}

}  // namespace shadowlab
