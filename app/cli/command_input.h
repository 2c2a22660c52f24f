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
// "" when pixel (x, y) lies in a width x height view, else why, naming the option and its text as given.
std::string checkPixelInView(const std::string& option, const std::string& text, int x, int y, int width, int height);

// Loads SCENE (a path or builtin:NAME) and prints the loader's warnings to stderr; on failure .error says why.
SceneLoadResult loadSceneForCommand(const std::string& spec);

// "" when a file can be written at path (its folder exists; it is a regular file or new; not a dangling symlink),
// else why not — checked before the work starts, with the rules of writeFileAtomically.
std::string checkOutputFolder(const std::string& path, const char* option);

// What a measurement holds per view pixel, summed over its buffers (G-buffer readback with double positions and
// normals, the tool's frame and shadow factor, reference classes and Lambert, boundary search, overlay: ~180
// bytes) with a margin: the figure behind checkMeasureMemory.
inline constexpr int kMeasureBytesPerPixel = 200;

// "" when a measurement of width x height fits in 80 % of the memory available now, else the figure and why.
std::string checkMeasureMemory(int width, int height);

}  // namespace shadowlab::cli
