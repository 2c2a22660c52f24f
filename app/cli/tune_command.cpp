#include "cli/tune_command.h"

#include "accuracy/bias_tuner.h"
#include "cli/accuracy_output.h"
#include "cli/command_input.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "scene/scene_source.h"
#include "settings/atomic_file.h"
#include "settings/preset_io.h"

#include <cstdio>
#include <iostream>

namespace shadowlab::cli {

namespace {

std::string stepLine(const TuneStep& s) {
    char line[256];
    std::snprintf(line, sizeof line, "%3d  %-28s %12.6g %7.3g %7.3g  %8.3f %8.3f %8.3f %8zu%s", s.index,
                  s.phase.c_str(), double(s.depthBias), double(s.slopeScaledDepthBias), double(s.normalOffset),
                  s.acnePercent, s.leakPercent, s.faintAcnePercent, s.mismatched, s.bestSoFar ? "  <- best" : "");
    return line;
}

}  // namespace

int runTune(const TuneOptions& options) {
    std::optional<Settings> settings = settingsFromCli(options.preset, options.overrides);
    if (!settings) return 2;
    if (std::string error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    if (std::string error = checkMeasureMemory(options.width, options.height); !error.empty()) return fail(error);
    if (!(options.maxAcnePercent >= 0.0 && options.maxAcnePercent <= 100.0))
        return fail("--max-acne must be a percentage in [0, 100]");
    for (const auto& [path, option] : {std::pair{options.out, "--out"}, std::pair{options.json, "--json"}})
        if (std::string error = checkOutputFolder(path, option); !error.empty()) return fail(error);
    SceneLoadResult loaded = loadSceneForCommand(options.scene);
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;

    try {
        HeadlessContext context;
        AccuracyMeter meter;
        const Camera camera = cameraFor(settings->camera, scene);
        std::cout << "tuning bias for " << scene.name << " at " << options.width << "x" << options.height
                  << ": least leak with acne <= " << options.maxAcnePercent << " %\n";
        std::cout << "  #  phase                           DepthBias   slope  normal    acne %   leak %  faint %"
                     "  mismatch\n";
        const TuneResult result =
            tuneBias(meter, scene, *settings, camera, options.width, options.height, options.maxAcnePercent, nullptr,
                     [&](const TuneStep& step) { std::cout << stepLine(step) << std::endl; });
        if (!result.ok) return fail(result.error);

        const ShadowMapSettings& best = result.best.shadow;
        std::cout << "\n" << (result.reachedLimit ? "result" : "NO setting reached acne <= " +
                                                                   std::to_string(options.maxAcnePercent) +
                                                                   " %; least acne found")
                  << ": DepthBias " << best.depthBias << ", SlopeScaledDepthBias " << best.slopeScaledDepthBias
                  << ", normal offset " << best.normalOffset << " texels (" << result.path.size()
                  << " candidates in " << result.seconds << " s)\n";
        printAccuracy(std::cout, result.report);
        AccuracyReport first;
        first.cost = result.referenceCost;
        std::cout << "the first candidate built the reference; later ones cost one tool frame each.\n";
        printAccuracyCost(std::cout, first);

        const std::string description =
            "Suggested by `shadowlab tune` for " + options.scene + " at " + std::to_string(options.width) + "x" +
            std::to_string(options.height) + ": acne " + std::to_string(result.report.acnePercent) + " %, leak " +
            std::to_string(result.report.leakPercent) + " %" +
            (result.reachedLimit ? "" : " (no setting reached the acne limit)") + ".";
        if (std::string error = savePresetFile(options.out, result.best, "tuned", description); !error.empty())
            return fail(error);
        std::cout << "wrote " << options.out << "\n";

        if (!options.json.empty()) {
            nlohmann::json path = nlohmann::json::array();
            for (const TuneStep& s : result.path)
                path.push_back({{"index", s.index}, {"phase", s.phase}, {"depthBias", s.depthBias},
                                {"slopeScaledDepthBias", s.slopeScaledDepthBias}, {"normalOffset", s.normalOffset},
                                {"acnePercent", s.acnePercent}, {"leakPercent", s.leakPercent},
                                {"faintAcnePercent", s.faintAcnePercent}, {"mismatched", s.mismatched},
                                {"withinLimit", s.withinLimit}, {"bestSoFar", s.bestSoFar}});
            const nlohmann::json json = {{"scene", options.scene},
                                         {"reachedLimit", result.reachedLimit},
                                         {"seconds", result.seconds},
                                         {"best", presetToJson(result.best)},
                                         {"report", accuracyToJson(result.report)},
                                         {"path", path}};
            // replace: a scene path that is not UTF-8 is written with U+FFFD rather than throwing.
            const std::string text = json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
            if (std::string error = writeFileAtomically(options.json, text); !error.empty())
                return fail(error);
            std::cout << "wrote " << options.json << "\n";
        }
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
