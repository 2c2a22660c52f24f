#pragma once
// The recently opened scenes: most recent first, at most kMaxRecentFiles, no duplicates (file paths compared in
// absolute, normalized form; "builtin:NAME" as written). Stored as JSON: {"recentFiles": ["...", ...]}.
#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab {

inline constexpr std::size_t kMaxRecentFiles = 10;

class RecentFiles {
public:
    // Puts `spec` first (moving it there if listed), drops the oldest beyond kMaxRecentFiles. Empty specs are ignored.
    void add(const std::string& spec);
    void remove(const std::string& spec);
    const std::vector<std::string>& items() const { return items_; }

private:
    std::vector<std::string> items_;
};

// The spec as stored: file paths absolute and normalized, "builtin:" specs unchanged.
std::string normalizedSceneSpec(const std::string& spec);

struct RecentFilesLoad {
    RecentFiles files;
    std::string error;  // "" also when the file does not exist yet (an empty list); else names the file and problem
};

RecentFilesLoad loadRecentFiles(const std::filesystem::path& file);
// Atomic (see atomic_file.h); creates the folder if missing. Returns "" or why it failed.
std::string saveRecentFiles(const std::filesystem::path& file, const RecentFiles& files);

}  // namespace shadowlab
