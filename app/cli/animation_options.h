#pragma once
// `--time SECONDS` and `--animation NAME|INDEX`, the same on every command that renders a scene: they are the
// animation.time and animation.play keys, applied after the command's --set overrides (so they win over a --set of
// the same key). Registered here once; each command's scene is posed from its settings (command_input.h).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace shadowlab::cli {

// Adds both options to `command`; what they hold is appended to `overrides` as key=value once parsing is done.
void addAnimationOptions(CLI::App& command, std::vector<std::string>& overrides);

}  // namespace shadowlab::cli
