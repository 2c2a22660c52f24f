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
#include "settings/settings_fields.h"
#include "shading/filters/filter_technique.h"

#include <algorithm>
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

// A trade-off candidate: its keys' values, the criterion's figures and what it cost.
std::string tradeOffLine(const TuneStep& s) {
    std::string line;
    char part[320];
    std::snprintf(part, sizeof part, "%3d  %-40s", s.index, s.phase.c_str());
    line += part;
    for (double v : s.tradeOff) {
        std::snprintf(part, sizeof part, " %10.4g", v);
        line += part;
    }
    std::snprintf(part, sizeof part, " %7.3f %9.5f %8.3f %8.3f %9.1f %8.1f%s", s.acnePercent, tradeOffError(s),
                  tradeOffBleeding(s), tradeOffDarkening(s), s.costMs, s.toolFrameMs, s.bestSoFar ? "  <- best" : "");
    return line + part;
}

std::string tradeOffHeader(const std::vector<std::string>& keys, bool soft) {
    std::string line = "  #  phase                                   ";
    for (const std::string& key : keys) {
        const std::string name = key.substr(key.rfind('.') + 1);
        char part[64];
        std::snprintf(part, sizeof part, " %10.10s", name.c_str());
        line += part;
    }
    return line + (soft ? "  acne %  soft|S-V|  bleed %   dark %   cost ms  tool ms"
                        : "  acne %    |S-V|   leak %   acne %   cost ms  tool ms");
}

// The technique declares keys of a light ("lights.#.size"): tuned per light, not only on the first.
bool hasLightKeys(const FilterTechnique& technique) {
    for (const TradeOffRange& range : technique.tradeOff)
        if (std::string(range.key).rfind("lights.#.", 0) == 0) return true;
    return false;
}

// A trade-off candidate's values by key (keys of the whole preset), for the JSON.
nlohmann::json tradeOffJson(const TuneResult& result, const TuneStep& s, std::size_t index) {
    nlohmann::json values = nlohmann::json::object();
    for (std::size_t k = 0; k < s.tradeOff.size() && k < result.tradeOffKeys.size(); ++k)
        values[keyOfLight(result.tradeOffKeys[k], index)] = s.tradeOff[k];
    return values;
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
    const std::optional<TuneSearch> search = parseTuneSearch(options.search);
    if (!search) return fail("--search must be auto, bias, technique or both, not '" + options.search + "'");
    const FilterTechnique& technique = filterTechnique(settings->filter.kind);

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
            // The technique's global keys (filter.*) are one setting for every light: tuned on the first light.
            TuneScope scope{*search, k == 0};
            if (k > 0 && !hasLightKeys(technique)) {
                if (scope.search == TuneSearch::TradeOff) {
                    std::cout << label << ": filter.kind " << technique.name << "'s keys are global, tuned on "
                              << lightLabel(indices[0], settings->lights[indices[0]].type) << "; nothing to tune\n";
                    continue;
                }
                if (scope.search == TuneSearch::Both) scope.search = TuneSearch::Bias;
            }
            const bool soft = one->lights[0].size > 0.0f;
            bool tradeOffHeaderShown = false;
            progress.above([&] {
                std::cout << "tuning " << label << " for " << scene.name << " at " << options.width << "x"
                          << options.height << " (filter.kind " << technique.name << ", --search "
                          << options.search << "), measured alone: acne <= " << options.maxAcnePercent << " %, then";
                if (scope.search != TuneSearch::TradeOff)
                    std::cout << " (bias) fewest wrong pixels beyond k, smallest edge error, smallest bias;";
                if (scope.search != TuneSearch::Bias && !technique.tradeOff.empty())
                    std::cout << " (technique) the least "
                              << (soft ? "mean |S-V| against the soft reference, then bleeding, over-darkening (lights." +
                                             std::to_string(index) + ".size > 0)"
                                       : std::string("mean |S-V|, then leak (lit umbra pixels), acne"));
                std::cout << "\n";
                if (scope.search == TuneSearch::Bias || scope.search == TuneSearch::Both ||
                    (scope.search == TuneSearch::Auto && technique.tradeOff.empty()))
                    std::cout << "  #  phase                                 DepthBias   slope  normal cull  rpb   acne %"
                                 "   leak %  wrong %  wrong>k edge tx\n";
            });
            const TuneResult result =
                tuneBias(meter, scene, *one, camera, options.width, options.height, options.maxAcnePercent,
                         &accuracyProgress,
                         [&](const TuneStep& step) {
                             progress.above([&] {
                                 if (!step.tradeOffStep) {
                                     std::cout << stepLine(step) << std::endl;
                                     return;
                                 }
                                 if (!tradeOffHeaderShown) {
                                     std::vector<std::string> keys;
                                     for (const TradeOffRange& range : technique.tradeOff)
                                         if (k == 0 || std::string(range.key).rfind("lights.#.", 0) == 0)
                                             keys.push_back(range.key);
                                     std::cout << tradeOffHeader(keys, step.soft) << "\n";
                                     tradeOffHeaderShown = true;
                                 }
                                 std::cout << tradeOffLine(step) << std::endl;
                             });
                         },
                         scope);
            progress.pause();  // the light's result is printed below
            if (!result.ok) return fail(label + ": " + result.error);

            const ShadowMapSettings& best = result.closest.lights[0].shadow;
            const std::string cull = cullModeName(best.cullMode);
            // The technique's values the search chose, and the criterion's figures there.
            nlohmann::json chosenValues = nlohmann::json::object();
            for (const std::string& key : result.tradeOffKeys)
                chosenValues[keyOfLight(key, index)] = findSettingsField(key)->get(result.closest);
            for (const std::string& clamp : result.startClamps) std::cout << "start: " << clamp << "\n";
            if (result.tradeOffSearched) {
                const TuneStep* bestStep = nullptr;
                for (const TuneStep& s : result.path)
                    if (s.tradeOffStep && s.bestSoFar) bestStep = &s;
                double candidatesMs = 0.0;
                std::size_t candidates = 0;
                for (const TuneStep& s : result.path)
                    if (s.tradeOffStep) candidatesMs += s.costMs, ++candidates;
                std::cout << "\n" << (result.reachedLimit ? "result" : "closest") << " (" << technique.name
                          << "): " << label << ":";
                for (auto it = chosenValues.begin(); it != chosenValues.end(); ++it)
                    std::cout << " " << it.key() << " " << it.value().dump();
                if (bestStep)
                    std::cout << "; acne " << bestStep->acnePercent << " %, "
                              << (bestStep->soft ? "soft mean |S-V| " : "mean |S-V| ") << tradeOffError(*bestStep) << ", "
                              << (bestStep->soft ? "bleeding " : "leak ") << tradeOffBleeding(*bestStep) << " %, "
                              << (bestStep->soft ? "over-darkening " : "acne ") << tradeOffDarkening(*bestStep) << " %";
                std::cout << " (" << candidates << " technique candidates, " << candidatesMs / 1000.0
                          << " s measuring)\n";
                if (result.reachedLimit)
                    for (auto it = chosenValues.begin(); it != chosenValues.end(); ++it)
                        findSettingsField(it.key())->set(tuned, it.value());
            }
            const bool biasSearched = std::any_of(result.path.begin(), result.path.end(),
                                                  [](const TuneStep& s) { return !s.tradeOffStep; });
            if (result.reachedLimit) {
                if (biasSearched)
                    std::cout << "\nresult: " << label << ": DepthBias " << best.depthBias
                              << ", SlopeScaledDepthBias " << best.slopeScaledDepthBias << ", normal offset "
                              << best.normalOffset << " texels, cullMode " << cull << ", receiverPlaneBias "
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
                                {"cascadeAcnePercent", s.cascadeAcnePercent}, {"tradeOffStep", s.tradeOffStep},
                                {"tradeOff", tradeOffJson(result, s, index)},
                                {"soft", s.soft
                                             ? nlohmann::json{{"meanError", s.softMeanError},
                                                              {"wrongPixelsPercent", s.softWrongPercent},
                                                              {"bleedingPercent", s.bleedingPercent},
                                                              {"overDarkeningPercent", s.overDarkeningPercent},
                                                              {"penumbraWidthErrorWorld", s.penumbraErrorWorld}}
                                             : nlohmann::json(nullptr)},
                                {"costMs", s.costMs}, {"toolFrameMs", s.toolFrameMs}});
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
                                  {"search", tuneSearchName(scope.search)},
                                  {"tradeOffSearched", result.tradeOffSearched},
                                  {"tradeOffKeys", result.tradeOffKeys},
                                  {"tradeOffChosen", chosenValues},
                                  {"startClamps", result.startClamps},
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
