#include "cli/bench_input.h"

#include "cli/command_input.h"
#include "cli/json_output.h"
#include "cli/settings_from_cli.h"

namespace shadowlab::cli {

BenchInput readBenchInput(const BenchOptions& options, bool checkView) {
    BenchInput input;
    input.settings = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!input.settings) {
        input.refused = 2;  // settingsFromCli printed why
        return input;
    }
    if (std::string error = checkOutputFolder(options.json, "--json"); !error.empty()) {
        input.refused = fail(error);
        return input;
    }
    if (checkView)
        if (std::string error = checkViewSize(options.width, options.height); !error.empty()) {
            input.refused = fail(error);
            return input;
        }
    input.loaded = loadSceneForCommand(options.scene, {&*input.settings});
    if (!input.loaded.scene) input.refused = fail(input.loaded.error);
    return input;
}

int writeBenchJson(const std::string& path, const nlohmann::json& doc) {
    if (path.empty()) return 0;
    if (std::string error = writeJsonOutput(path, doc); !error.empty()) return fail("--json " + path + ": " + error);
    return 0;
}

}  // namespace shadowlab::cli
