#include "cli/command_input.h"

#include "settings/regular_file.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace shadowlab::cli {

int fail(const std::string& message) {
    std::cerr << "error: " << message << "\n";
    return 1;
}

std::string checkPixelInView(const std::string& option, const std::string& text, int x, int y, int width, int height) {
    if (x >= 0 && y >= 0 && x < width && y < height) return "";
    return option + " " + text + " is outside the " + std::to_string(width) + "x" + std::to_string(height) +
           " view (x in [0, " + std::to_string(width - 1) + "], y in [0, " + std::to_string(height - 1) + "])";
}

std::string checkViewSize(int width, int height) {
    if (width >= 1 && height >= 1 && width <= 16384 && height <= 16384) return "";
    return "--width/--height must be in [1, 16384], got " + std::to_string(width) + "x" + std::to_string(height);
}

SceneLoadResult loadSceneForCommand(const std::string& spec) {
    SceneLoadResult loaded = loadScene(spec);
    if (loaded.scene)
        for (const std::string& w : loaded.scene->warnings)
            std::cerr << "warning: " << loaded.scene->name << ": " << w << "\n";
    return loaded;
}

std::string checkOutputFolder(const std::string& path, const char* option) {
    namespace fs = std::filesystem;
    if (path.empty()) return {};
    const std::string where = std::string(option) + " " + path + ": ";
    std::error_code ec;
    // What the atomic writer will refuse at the end is refused before the work: only regular files are written.
    if (fs::is_symlink(fs::symlink_status(path, ec)) && !fs::exists(path, ec))
        return where + "a symbolic link to '" + fs::read_symlink(path, ec).string() +
               "', which does not exist (ShadowLab does not create files through dangling links)";
    if (const std::string kind = nonRegularFileKind(path); !kind.empty())
        return where + "it is " + kind + ", not a regular file; ShadowLab writes only regular files";
    const fs::path folder = fs::path(path).parent_path();
    if (folder.empty() || fs::is_directory(folder, ec)) return {};
    return where + "folder '" + folder.string() + "' does not exist";
}

std::string checkMeasureMemory(int width, int height) {
    const double bytes = double(width) * double(height) * kMeasureBytesPerPixel;
    const long pages = ::sysconf(_SC_AVPHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return {};
    const double available = double(pages) * double(pageSize);
    if (bytes <= 0.8 * available) return {};
    auto gib = [](double b) {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f GiB", b / double(1u << 30));
        return std::string(text);
    };
    return "--width/--height " + std::to_string(width) + "x" + std::to_string(height) + ": a measurement needs about " +
           gib(bytes) + " of memory (" + std::to_string(kMeasureBytesPerPixel) + " bytes a pixel), more than the " +
           gib(available) + " available; use a smaller view";
}

}  // namespace shadowlab::cli
