#pragma once
// What the bench modes share around their work: what they read before it, in one order (the settings of --preset
// and --set, the --json folder, the view size, then the scene), and the --json file they write after it.
#include "cli/bench_command.h"
#include "scene/scene_source.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>

namespace shadowlab::cli {

struct BenchInput {
    std::optional<Settings> settings;  // --preset with --set applied
    SceneLoadResult loaded;            // the scene of --scene
    int refused = 0;                   // non-zero: the exit status, the reason already printed
};

// `checkView`: whether --width/--height must be a view that can be rendered (the modes that render or trace one).
BenchInput readBenchInput(const BenchOptions& options, bool checkView = true);

// Writes `doc` to the --json file `path` when one is given: 0, or the exit status of the failure, its message
// "--json PATH: why" printed.
int writeBenchJson(const std::string& path, const nlohmann::json& doc);

}  // namespace shadowlab::cli
