#pragma once
// `shadowlab edit` (and `shadowlab` with no arguments): the editor in a GLFW window.
#include "scene/scene_source.h"

#include <string>

namespace shadowlab::editor_window {

struct EditOptions {
    std::string scene = kDefaultSceneSpec;
    std::string preset;  // path or shipped name; empty = "default"
    int width = 1600;
    int height = 900;
    std::string screenshotDir;  // empty: the user's data folder (userScreenshotsDir())
};

// Runs until the window closes. Without a display (or GL 4.5) it says so and returns 1.
int runEdit(const EditOptions& options);

}  // namespace shadowlab::editor_window
