#include "cli/command_input.h"

#include <filesystem>
#include <iostream>

namespace shadowlab::cli {

int fail(const std::string& message) {
    std::cerr << "error: " << message << "\n";
    return 1;
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
    if (path.empty()) return {};
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (folder.empty() || std::filesystem::is_directory(folder)) return {};
    return std::string(option) + " " + path + ": folder '" + folder.string() + "' does not exist";
}

}  // namespace shadowlab::cli
