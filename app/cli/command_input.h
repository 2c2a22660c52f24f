#pragma once
// What every CLI command does before its work: report a failure, check the view size and output folders, load the
// scene.
#include "scene/scene_source.h"

#include <string>

namespace shadowlab::cli {

// Prints "error: message" to stderr and returns 1, the exit code of a command that failed.
int fail(const std::string& message);

// "" when --width/--height can be rendered, else why not.
std::string checkViewSize(int width, int height);

// Loads SCENE (a path or builtin:NAME) and prints the loader's warnings to stderr; on failure .error says why.
SceneLoadResult loadSceneForCommand(const std::string& spec);

// "" when a file can be created at path (its folder exists), else why not — checked before the work starts.
std::string checkOutputFolder(const std::string& path, const char* option);

}  // namespace shadowlab::cli
