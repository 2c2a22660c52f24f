// The user's own files: config and preset folders from the environment, the recent-files list (order, limit,
// duplicates, atomic JSON round trip, clear errors), the preset catalog (shipped read-only + user folder) and where a
// binary finds its shipped data.
#include "settings/preset_catalog.h"
#include "settings/recent_files.h"
#include "settings/shipped_data.h"
#include "settings/user_config.h"
#include "../support/as_unprivileged_user.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        std::random_device rd;
        path = fs::temp_directory_path() / ("shadowlab_user_files_" + std::to_string(rd()) + std::to_string(rd()));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

// Sets (or unsets, for nullopt) an environment variable for one test, restoring it afterwards.
class ScopedEnv {
public:
    ScopedEnv(const char* name, std::optional<std::string> value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value) ::setenv(name, value->c_str(), 1);
        else ::unsetenv(name);
    }
    ~ScopedEnv() {
        if (old_) ::setenv(name_, old_->c_str(), 1);
        else ::unsetenv(name_);
    }

private:
    const char* name_;
    std::optional<std::string> old_;
};

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST(UserConfig, ConfigFolderFollowsShadowlabThenXdgThenHome) {
    ScopedEnv home("HOME", "/home/alice");
    {
        ScopedEnv config("SHADOWLAB_CONFIG_DIR", "/tmp/own-config");
        ScopedEnv xdg("XDG_CONFIG_HOME", "/xdg");
        EXPECT_EQ(userConfigDir(), fs::path("/tmp/own-config"));
    }
    {
        ScopedEnv config("SHADOWLAB_CONFIG_DIR", std::nullopt);
        ScopedEnv xdg("XDG_CONFIG_HOME", "/xdg");
        EXPECT_EQ(userConfigDir(), fs::path("/xdg/shadowlab"));
        EXPECT_EQ(recentFilesPath(), fs::path("/xdg/shadowlab/recent-files.json"));
    }
    {
        ScopedEnv config("SHADOWLAB_CONFIG_DIR", "");  // empty counts as unset
        ScopedEnv xdg("XDG_CONFIG_HOME", "");
        EXPECT_EQ(userConfigDir(), fs::path("/home/alice/.config/shadowlab"));
    }
}

TEST(UserConfig, UserPresetsFolderIsItsOwnVariableElseInsideTheConfigFolder) {
    ScopedEnv config("SHADOWLAB_CONFIG_DIR", "/cfg");
    {
        ScopedEnv presets("SHADOWLAB_USER_PRESETS", "/my/presets");
        EXPECT_EQ(userPresetsDir(), fs::path("/my/presets"));
    }
    ScopedEnv presets("SHADOWLAB_USER_PRESETS", std::nullopt);
    EXPECT_EQ(userPresetsDir(), fs::path("/cfg/presets"));
}

TEST(UserConfig, ScreenshotsGoToTheUsersDataFolder) {
    ScopedEnv home("HOME", "/home/alice");
    {
        ScopedEnv own("SHADOWLAB_SCREENSHOTS", "/shots");
        ScopedEnv xdg("XDG_DATA_HOME", "/xdg-data");
        EXPECT_EQ(userScreenshotsDir(), fs::path("/shots"));
    }
    {
        ScopedEnv own("SHADOWLAB_SCREENSHOTS", "");
        ScopedEnv xdg("XDG_DATA_HOME", "/xdg-data");
        EXPECT_EQ(userScreenshotsDir(), fs::path("/xdg-data/shadowlab/screenshots"));
    }
    ScopedEnv own("SHADOWLAB_SCREENSHOTS", std::nullopt);
    ScopedEnv xdg("XDG_DATA_HOME", std::nullopt);
    EXPECT_EQ(userScreenshotsDir(), fs::path("/home/alice/.local/share/shadowlab/screenshots"));
}

TEST(UserConfig, EnsureFolderCreatesParentsAndRefusesAFile) {
    TempDir dir;
    EXPECT_EQ(ensureFolder(dir.path / "a" / "b"), "");
    EXPECT_TRUE(fs::is_directory(dir.path / "a" / "b"));
    writeText(dir.path / "file", "x");
    EXPECT_NE(ensureFolder(dir.path / "file").find("not a folder"), std::string::npos);
    EXPECT_NE(ensureFolder(dir.path / "file" / "sub").find("cannot create folder"), std::string::npos);
}

// A folder under one that may not be searched: its type cannot be read, which is not "a file" (the real cause is
// the permission). Checked as user nobody, so it holds when the tests run as root (CI, a fresh Debian root).
TEST(UserConfig, EnsureFolderUnderAnUnsearchableFolderNamesThePermission) {
    TempDir dir;
    const fs::path closed = dir.path / "closed";
    fs::create_directories(closed / "inside");
    fs::permissions(closed, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);  // no search
    std::string error;
    {
        const test::AsUnprivilegedUser user;
        EXPECT_EQ(user.error(), "");
        error = ensureFolder(closed / "inside");
    }
    fs::permissions(closed, fs::perms::owner_all);
    EXPECT_EQ(error.find("not a folder"), std::string::npos) << error;
    EXPECT_NE(error.find("Permission denied"), std::string::npos) << error;
    EXPECT_NE(error.find((closed / "inside").string()), std::string::npos) << error;
}

TEST(RecentFiles, MostRecentFirstWithoutDuplicatesAndAtMostTen) {
    TempDir dir;
    RecentFiles recent;
    recent.add("builtin:textbook");
    recent.add((dir.path / "a.gltf").string());
    recent.add("builtin:fence");
    // The same file through another spelling moves to the front instead of appearing twice.
    recent.add((dir.path / "sub" / ".." / "a.gltf").string());
    ASSERT_EQ(recent.items().size(), 3u);
    EXPECT_EQ(recent.items()[0], (dir.path / "a.gltf").string());
    EXPECT_EQ(recent.items()[1], "builtin:fence");
    EXPECT_EQ(recent.items()[2], "builtin:textbook");

    for (int i = 0; i < 12; ++i) recent.add((dir.path / ("scene" + std::to_string(i) + ".glb")).string());
    ASSERT_EQ(recent.items().size(), kMaxRecentFiles);
    EXPECT_EQ(recent.items().front(), (dir.path / "scene11.glb").string());
    EXPECT_EQ(recent.items().back(), (dir.path / "scene2.glb").string());

    recent.add("");
    EXPECT_EQ(recent.items().size(), kMaxRecentFiles);
    recent.remove((dir.path / "scene11.glb").string());
    EXPECT_EQ(recent.items().front(), (dir.path / "scene10.glb").string());
}

TEST(RecentFiles, RelativePathsAreStoredAbsolute) {
    RecentFiles recent;
    recent.add("scenes/x.gltf");
    EXPECT_EQ(recent.items().front(), (fs::current_path() / "scenes/x.gltf").string());
}

TEST(RecentFiles, SaveCreatesTheFolderAndLoadsBackInOrder) {
    TempDir dir;
    RecentFiles recent;
    recent.add("builtin:textbook");
    recent.add("/data/b.glb");
    recent.add("/data/c.gltf");
    const fs::path file = dir.path / "config" / "shadowlab" / "recent-files.json";
    ASSERT_EQ(saveRecentFiles(file, recent), "");
    RecentFilesLoad loaded = loadRecentFiles(file);
    EXPECT_EQ(loaded.error, "");
    EXPECT_EQ(loaded.files.items(), recent.items());
    // No temporary left beside it.
    int entries = 0;
    for (const auto& e : fs::directory_iterator(file.parent_path())) entries += e.is_regular_file();
    EXPECT_EQ(entries, 1);
}

TEST(RecentFiles, MissingFileIsAnEmptyListBrokenFileSaysWhy) {
    TempDir dir;
    RecentFilesLoad missing = loadRecentFiles(dir.path / "none.json");
    EXPECT_EQ(missing.error, "");
    EXPECT_TRUE(missing.files.items().empty());

    writeText(dir.path / "broken.json", "{\"recentFiles\": [\"a\",");
    RecentFilesLoad broken = loadRecentFiles(dir.path / "broken.json");
    EXPECT_NE(broken.error.find("broken.json"), std::string::npos);
    EXPECT_NE(broken.error.find("not valid JSON"), std::string::npos);

    writeText(dir.path / "wrong.json", "[1, 2]");
    EXPECT_NE(loadRecentFiles(dir.path / "wrong.json").error.find("recentFiles"), std::string::npos);

    // A hand-edited file with duplicates and too many entries is cleaned up on load.
    std::string many = "{\"recentFiles\": [\"/x/0.glb\", \"/x/0.glb\"";
    for (int i = 1; i < 15; ++i) many += ", \"/x/" + std::to_string(i) + ".glb\"";
    writeText(dir.path / "many.json", many + "]}");
    RecentFilesLoad cleaned = loadRecentFiles(dir.path / "many.json");
    ASSERT_EQ(cleaned.files.items().size(), kMaxRecentFiles);
    EXPECT_EQ(cleaned.files.items().front(), "/x/0.glb");
    EXPECT_EQ(cleaned.files.items().back(), "/x/9.glb");
}

TEST(RecentFiles, SaveIntoAPathUnderAFileFailsAndSaysWhy) {
    TempDir dir;
    writeText(dir.path / "plain", "x");
    RecentFiles recent;
    recent.add("builtin:textbook");
    const std::string error = saveRecentFiles(dir.path / "plain" / "recent-files.json", recent);
    EXPECT_NE(error.find("cannot save the recent files list"), std::string::npos) << error;
    EXPECT_NE(error.find("plain"), std::string::npos) << error;
}

TEST(PresetCatalog, ShippedPresetsAreReadOnlyAndUserPresetsFollowSorted) {
    TempDir user;
    writeText(user.path / "zeta.json", "{}");
    writeText(user.path / "alpha.json", "{}");
    writeText(user.path / "notes.txt", "not a preset");
    writeText(user.path / ".alpha.json.tmp-1-2", "temporary");
    std::vector<PresetEntry> all = listPresets(fs::path(SHADOWLAB_SOURCE_DIR) / "presets", user.path);

    std::vector<std::string> shipped, mine;
    for (const PresetEntry& e : all) (e.readOnly ? shipped : mine).push_back(e.name);
    EXPECT_EQ(shipped, (std::vector<std::string>{"acne", "courtyard", "default", "pcf-wide", "peter-panning", "room", "soft"}));
    EXPECT_EQ(mine, (std::vector<std::string>{"alpha", "zeta"}));
    EXPECT_TRUE(all.front().readOnly);  // shipped first
    EXPECT_FALSE(all.back().readOnly);
    EXPECT_EQ(all.back().path, user.path / "zeta.json");
}

TEST(PresetCatalog, MissingUserFolderAndSameFolderTwice) {
    const fs::path shipped = fs::path(SHADOWLAB_SOURCE_DIR) / "presets";
    EXPECT_EQ(listPresets(shipped, "/nonexistent/presets").size(), 7u);
    std::vector<PresetEntry> twice = listPresets(shipped, shipped);
    EXPECT_EQ(twice.size(), 7u);
    for (const PresetEntry& e : twice) EXPECT_TRUE(e.readOnly);
    EXPECT_TRUE(listPresets("/nonexistent/a", "/nonexistent/b").empty());
}

// Every command's --preset and the editor's resolve a name the same way: a file, else shipped, else the user's.
TEST(PresetCatalog, FindPresetTakesAPathThenAShippedNameThenAUserName) {
    const fs::path shipped = fs::path(SHADOWLAB_SOURCE_DIR) / "presets";
    TempDir user;
    writeText(user.path / "street.json", "{}");
    writeText(user.path / "soft.json", "{}");  // named like a shipped one: the shipped one wins, as the list shows

    const std::optional<PresetEntry> mine = findPreset("street", shipped, user.path);
    ASSERT_TRUE(mine.has_value());
    EXPECT_EQ(mine->path, user.path / "street.json");
    EXPECT_FALSE(mine->readOnly);
    ASSERT_TRUE(findPreset("street.json", shipped, user.path).has_value());

    const std::optional<PresetEntry> soft = findPreset("soft", shipped, user.path);
    ASSERT_TRUE(soft.has_value());
    EXPECT_EQ(soft->path, shipped / "soft.json");
    EXPECT_TRUE(soft->readOnly);

    const std::optional<PresetEntry> byPath = findPreset((user.path / "soft.json").string(), shipped, user.path);
    ASSERT_TRUE(byPath.has_value());
    EXPECT_EQ(byPath->path, user.path / "soft.json");
    EXPECT_FALSE(byPath->readOnly);
    const std::optional<PresetEntry> shippedByPath = findPreset((shipped / "acne.json").string(), shipped, user.path);
    ASSERT_TRUE(shippedByPath.has_value());
    EXPECT_TRUE(shippedByPath->readOnly);

    EXPECT_FALSE(findPreset("nonesuch", shipped, user.path).has_value());
    EXPECT_FALSE(findPreset("sub/street", shipped, user.path).has_value());  // a name is not a path into a folder
    EXPECT_FALSE(findPreset("", shipped, user.path).has_value());
}

// The shipped data is found from the binary's own folder: an installed prefix anywhere, nothing else.
TEST(ShippedData, FoundBesideTheBinaryWhereverThePrefixIs) {
    TempDir prefix;
    fs::create_directories(prefix.path / "bin");
    fs::create_directories(prefix.path / "share" / "shadowlab" / "presets");
    const ShippedData found = findShippedData(prefix.path / "bin" / "shadowlab");
    EXPECT_EQ(found.dir, prefix.path / "share" / "shadowlab");
    EXPECT_TRUE(found.problem.empty()) << found.problem;
}

TEST(ShippedData, NoneFoundNamesThePathTriedAndTheBinary) {
    TempDir prefix;
    fs::create_directories(prefix.path / "bin");
    fs::create_directories(prefix.path / "share" / "shadowlab");  // a data folder without presets/ does not count
    const fs::path binary = prefix.path / "bin" / "shadowlab";
    const ShippedData found = findShippedData(binary);
    EXPECT_TRUE(found.dir.empty());
    EXPECT_EQ(found.tried, prefix.path / "share" / "shadowlab");
    EXPECT_NE(found.problem.find((prefix.path / "share" / "shadowlab" / "presets").string()), std::string::npos)
        << found.problem;
    EXPECT_NE(found.problem.find(binary.string()), std::string::npos) << found.problem;
}

// The test binary runs from the build tree (build/tests), whose share/shadowlab links to the source tree's presets.
TEST(ShippedData, TheBuildTreeFindsTheSourcePresets) {
    const ShippedData& data = shippedData();
    ASSERT_TRUE(data.problem.empty()) << data.problem;
    EXPECT_TRUE(fs::equivalent(shippedPresetsDir(), fs::path(SHADOWLAB_SOURCE_DIR) / "presets"));
}
