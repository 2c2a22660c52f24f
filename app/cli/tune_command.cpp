#include "cli/tune_command.h"

#include "accuracy/bias_tuner.h"
#include "accuracy/light_isolation.h"
#include "cli/accuracy_output.h"
#include "cli/command_input.h"
#include "cli/progress.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "scene/scene_source.h"
#include "settings/atomic_file.h"
#include "settings/preset_io.h"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace shadowlab::cli {

namespace {

std::string stepLine(const TuneStep& s) {
    char line[256];
    std::snprintf(line, sizeof line, "%3d  %-34s %12.6g %7.3g %7.3g %-5s %-3s %8.3f %8.3f %8.3f %8zu %7.2f%s", s.index,
                  s.phase.c_str(), double(s.depthBias), double(s.slopeScaledDepthBias), double(s.normalOffset),
                  cullModeName(s.cullMode).c_str(), s.receiverPlaneBias ? "on" : "off",
                  s.acnePercent, s.leakPercent, s.wrongPercent, s.wrongBeyondK, s.edgeErrorTexels,
                  s.bestSoFar ? "  <- best" : "");
    return line;
}

// The tuner keeps shadow.depthBiasClamp as given: it caps what any candidate's constant and slope bias can do.
std::string clampNote(float clamp) {
    std::ostringstream text;
    text << "; shadow.depthBiasClamp " << clamp
         << " (kept as given) caps every candidate's constant + slope bias: raise it or set it to 0";
    return text.str();
}

}  // namespace

int runTune(const TuneOptions& options) {
    std::optional<Settings> settings = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!settings) return 2;
    if (std::string error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    if (std::string error = checkMeasureMemory(options.width, options.height); !error.empty()) return fail(error);
    if (!(options.maxAcnePercent >= 0.0 && options.maxAcnePercent <= 100.0))
        return fail("--max-acne must be a percentage in [0, 100]");
    if (std::string error = checkOutputs({{options.out, "--out"}, {options.json, "--json"}},
                                         {{options.scene, "--scene"}, {options.preset, "--preset"}});
        !error.empty())
        return fail(error);
    SceneLoadResult loaded = loadSceneForCommand(options.scene, {&*settings});
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;
    std::string chooseError;
    const std::optional<std::vector<std::size_t>> chosen = chooseLights(*settings, scene, options.light, "tune", chooseError);
    if (!chosen) return fail(chooseError);
    const std::vector<std::size_t>& indices = *chosen;

    try {
        HeadlessContext context;
        AccuracyMeter meter;
        const Camera camera = cameraFor(settings->camera, scene, double(options.width) / options.height);
        Settings tuned = *settings;  // every other setting as given; each tuned light's shadow goes into lights[N]
        bool allReached = true;
        std::string summary;
        nlohmann::json lightsJson = nlohmann::json::array();
        AccuracyProgress accuracyProgress;
        ProgressLine progress(
            "tune", indices.size(), "lights", [&] { return double(accuracyProgress.fraction.load()); },
            [&] { return accuracyProgress.stage(); });
        for (std::size_t k = 0; k < indices.size(); ++k) {
            const std::size_t index = indices[k];
            progress.setDone(k);
            accuracyProgress.fraction = 0.0f;
            progress.resume();
            std::string error;
            const std::optional<Settings> one = isolateLight(*settings, scene, index, error);
            if (!one) return fail(error);
            const std::string label = lightLabel(index, one->lights[0].type);
            progress.above([&] {
                std::cout << "tuning bias of " << label << " for " << scene.name << " at " << options.width << "x"
                          << options.height << ", measured alone: acne <= " << options.maxAcnePercent
                          << " %, then fewest wrong pixels beyond k, smallest edge error, smallest bias\n";
                std::cout << "  #  phase                                 DepthBias   slope  normal cull  rpb   acne %"
                             "   leak %  wrong %  wrong>k edge tx\n";
            });
            const TuneResult result =
                tuneBias(meter, scene, *one, camera, options.width, options.height, options.maxAcnePercent,
                         &accuracyProgress,
                         [&](const TuneStep& step) {
                             progress.above([&] { std::cout << stepLine(step) << std::endl; });
                         });
            progress.pause();  // the light's result is printed below
            if (!result.ok) return fail(label + ": " + result.error);

            const ShadowMapSettings& best = result.closest.lights[0].shadow;
            const std::string cull = cullModeName(best.cullMode);
            if (result.reachedLimit) {
                std::cout << "\nresult: " << label << ": DepthBias " << best.depthBias << ", SlopeScaledDepthBias "
                          << best.slopeScaledDepthBias << ", normal offset " << best.normalOffset
                          << " texels, cullMode " << cull << ", receiverPlaneBias "
                          << (best.receiverPlaneBias ? "true" : "false") << " (" << result.path.size()
                          << " candidates in " << result.seconds << " s)\n";
                if (const std::string why = receiverPlaneChoice(result); !why.empty()) std::cout << why << "\n";
                if (!result.report.cascades.cascades.empty()) {  // the one setting, judged in every cascade
                    std::cout << "holds in every cascade:";
                    for (const CascadeNumbers& c : result.report.cascades.cascades)
                        std::cout << " cascade:" << c.cascade << " acne " << c.acnePercent << " % (texel "
                                  << c.texelWorldSize << ", " << c.measured << " pixels"
                                  << (c.measured < kTuneCascadeMinPixels ? ", too few to judge alone" : "") << ");";
                    std::cout << "\n";
                }
                setLightShadow(tuned, index, result.best.lights[0].shadow);
                summary += " " + label + ": acne " + std::to_string(result.report.acnePercent) + " %, leak " +
                           std::to_string(result.report.leakPercent) + " %, wrong pixels " +
                           std::to_string(result.report.wrongPercent) + " %.";
            } else {
                allReached = false;
                const CauseInfo& blocking = causeInfo(result.blockingCause);
                std::cout << "\n" << label << ": NO setting reached acne <= " << options.maxAcnePercent << " %";
                if (result.blockingCascade >= 0)  // a cascade's acne stays above the limit
                    std::cout << " in every cascade: cascade:" << result.blockingCascade << " of " << label
                              << " stops it: its " << result.blockingCascadePixels
                              << " measured pixels keep acne above the limit with every candidate (least "
                              << result.blockingCascadeLeastAcne << " %; " << result.blockingCascadeAcne
                              << " % at the closest candidate; texel " << result.blockingCascadeTexel
                              << " world units; " << blocking.name << ", " << blocking.remedy
                              << (best.depthBiasClamp > 0.0f ? clampNote(best.depthBiasClamp) : std::string())
                              << "). Overall acne there: ";
                else
                    std::cout << ": stopped by " << blocking.name << " (" << blocking.remedy << "). Least acne: ";
                std::cout << result.report.acnePercent << " % at DepthBias " << best.depthBias
                          << ", SlopeScaledDepthBias " << best.slopeScaledDepthBias << ", normal offset "
                          << best.normalOffset << " texels, cullMode " << cull << " (" << result.path.size()
                          << " candidates in " << result.seconds << " s). No preset written.\n";
            }
            printAccuracy(std::cout, result.report);
            AccuracyReport first;
            first.cost = result.referenceCost;
            std::cout << "the first candidate built the reference; later ones cost one tool frame each.\n";
            printAccuracyCost(std::cout, first);

            nlohmann::json path = nlohmann::json::array();
            for (const TuneStep& s : result.path)
                path.push_back({{"index", s.index}, {"phase", s.phase}, {"depthBias", s.depthBias},
                                {"slopeScaledDepthBias", s.slopeScaledDepthBias}, {"normalOffset", s.normalOffset},
                                {"cullMode", cullModeName(s.cullMode)}, {"receiverPlaneBias", s.receiverPlaneBias},
                                {"acnePercent", s.acnePercent}, {"leakPercent", s.leakPercent},
                                {"wrongPixelsPercent", s.wrongPercent}, {"wrongBeyondK", s.wrongBeyondK},
                                {"meanError", s.meanError}, {"edgeErrorP95Texels", s.edgeErrorTexels},
                                {"withinLimit", s.withinLimit}, {"bestSoFar", s.bestSoFar},
                                {"cascadeAcnePercent", s.cascadeAcnePercent}});
            lightsJson.push_back({{"index", index},
                                  {"reachedLimit", result.reachedLimit},
                                  {"blockingCause", causeInfo(result.blockingCause).key},
                                  {"blockingCascade", result.blockingCascade},
                                  {"blockingCascadePixels", result.blockingCascadePixels},
                                  {"blockingCascadeTexelWorldSize", result.blockingCascadeTexel},
                                  {"blockingCascadeAcnePercent", result.blockingCascadeAcne},
                                  {"blockingCascadeLeastAcnePercent", result.blockingCascadeLeastAcne},
                                  {"seconds", result.seconds},
                                  {"closest",
                                   {{"depthBias", best.depthBias}, {"slopeScaledDepthBias", best.slopeScaledDepthBias},
                                    {"normalOffset", best.normalOffset}, {"cullMode", cull},
                                    {"receiverPlaneBias", best.receiverPlaneBias}}},
                                  {"receiverPlaneChoice", receiverPlaneChoice(result)},
                                  {"report", accuracyToJson(result.report)},
                                  {"path", path}});
        }

        if (allReached) {
            const std::string description = "Suggested by `shadowlab tune` for " + options.scene + " at " +
                                            std::to_string(options.width) + "x" + std::to_string(options.height) +
                                            " (metrics version 2):" + summary;
            // The preset records the scene and the camera the bias was tuned from, so that view comes back.
            tuned.camera = recordedCamera(camera, settings->camera.autoFrame);
            tuned.camera.sceneCamera = settings->camera.sceneCamera;
            if (std::string error = savePresetFile(options.out, tuned, "tuned", description, options.scene);
                !error.empty())
                return fail(error);
            std::cout << "wrote " << options.out << "\n";
        }

        if (!options.json.empty()) {
            const nlohmann::json json = {{"scene", options.scene},
                                         {"reachedLimit", allReached},
                                         {"best", allReached ? presetToJson(tuned) : nullptr},
                                         {"lights", lightsJson}};
            // replace: a scene path that is not UTF-8 is written with U+FFFD rather than throwing.
            const std::string text = json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
            if (std::string error = writeFileAtomically(options.json, text); !error.empty())
                return fail(error);
            std::cout << "wrote " << options.json << "\n";
        }
        if (!allReached) return kNoSettingReachedLimit;
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
