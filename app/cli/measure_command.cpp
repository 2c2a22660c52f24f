#include "cli/measure_command.h"

#include "accuracy/accuracy_meter.h"
#include "accuracy/light_accuracy.h"
#include "accuracy/light_isolation.h"
#include "cli/accuracy_output.h"
#include "cli/command_input.h"
#include "cli/measure_motion.h"
#include "cli/measure_stale_bounds.h"
#include "cli/progress.h"
#include "cli/remeasure_bench.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "image/image_io.h"
#include "light/scene_lights.h"
#include "scene/scene_source.h"
#include "settings/atomic_file.h"

#include <iostream>

namespace shadowlab::cli {

int runMeasure(const MeasureOptions& options) {
    if (!options.staleBounds.empty()) return runMeasureStaleBounds(options);
    if (wantsMotion(options)) return runMeasureMotion(options);
    std::optional<Settings> settings = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!settings) return 2;
    if (std::string error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    // The pictures' limits first: they hold on any machine, the memory check depends on this one.
    for (const NamedPath& overlay : {NamedPath{options.overlay, "--overlay"}, NamedPath{options.causeOverlay, "--cause-overlay"},
                                     NamedPath{options.softOverlay, "--soft-overlay"}})
        if (std::string error = checkPictureOutput(overlay, {options.width, options.height, 4, 4, true, {}}); !error.empty())
            return fail(error);
    if (std::string error = checkMeasureMemory(options.width, options.height); !error.empty()) return fail(error);
    if (std::string error = checkOutputs({{options.json, "--json"}, {options.overlay, "--overlay"},
                                          {options.causeOverlay, "--cause-overlay"},
                                          {options.softOverlay, "--soft-overlay"}},
                                         {{options.scene, "--scene"}, {options.preset, "--preset"}});
        !error.empty())
        return fail(error);
    SceneLoadResult loaded = loadSceneForCommand(options.scene, {&*settings});
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;
    std::optional<std::size_t> only;
    if (options.light >= 0) {
        if (std::string why = unmeasurableReason(*settings, scene, std::size_t(options.light)); !why.empty())
            return fail("--light " + std::to_string(options.light) + ": " + why);
        only = std::size_t(options.light);
    }

    try {
        HeadlessContext context;
        AccuracyMeter meter;
        const Camera camera = cameraFor(settings->camera, scene, double(options.width) / options.height);
        AccuracyProgress accuracyProgress;
        ProgressLine progress(
            "measure", 0, "", [&] { return double(accuracyProgress.fraction.load()); },
            [&] { return accuracyProgress.stage(); });
        const ManyLightsReport many =
            measureLights(meter, scene, *settings, camera, options.width, options.height, only, &accuracyProgress);
        progress.finish();
        if (!many.ok) return fail(many.error);
        for (const LightAccuracy& light : many.lights)
            for (const std::string& w : light.report.warnings)
                std::cerr << "warning: " << lightLabel(light.index, light.type) << ": " << w << "\n";
        std::cout << "scene " << scene.name << " (" << scene.triangleCount() << " triangles), "
                  << describeLightSource(*settings, scene) << "\n";
        printManyLights(std::cout, many);
        if (!options.json.empty()) {
            nlohmann::json json = manyLightsToJson(many);
            json["scene"] = options.scene;
            json["preset"] = options.preset;
            // replace: a scene path that is not UTF-8 is written with U+FFFD rather than throwing.
            const std::string text = json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
            if (std::string error = writeFileAtomically(options.json, text); !error.empty())
                return fail(error);
            std::cout << "wrote " << options.json << "\n";
        }
        // One light: its overlay; several: their union, each pixel coloured by its worst light.
        const std::string which = only ? lightLabel(*only, many.lights.front().type)
                                       : many.lights.size() == 1 ? lightLabel(many.lights.front().index,
                                                                             many.lights.front().type)
                                                                 : "all lights, coloured by each pixel's worst";
        for (const auto& [path, kind] : {std::pair{options.overlay, OverlayKind::Error},
                                         std::pair{options.causeOverlay, OverlayKind::Cause}}) {
            if (path.empty()) continue;
            const std::vector<std::uint8_t>& rgba =
                kind == OverlayKind::Error ? many.overlayRgba : many.causeOverlayRgba;
            if (std::string error = writePng(path, many.width, many.height, 4, rgba.data(), false); !error.empty())
                return fail(error);
            std::cout << "wrote " << path << " (" << which << ": " << legendText(kind) << "; the rest dimmed)\n";
        }
        if (!options.softOverlay.empty()) {
            // One light against its own soft reference: the union of several lights' soft V has no meaning.
            if (many.lights.size() != 1)
                return fail("--soft-overlay colours one light against its soft reference; " +
                            std::to_string(many.lights.size()) + " lights were measured: choose one with --light N");
            const LightAccuracy& light = many.lights.front();
            const std::string label = lightLabel(light.index, light.type);
            if (light.report.softOverlayRgba.empty())
                return fail("--soft-overlay: " + label + " has no size (lights." + std::to_string(light.index) +
                            ".size is 0), so there is no soft reference to compare with");
            if (std::string error = writePng(options.softOverlay, many.width, many.height, 4,
                                             light.report.softOverlayRgba.data(), false);
                !error.empty())
                return fail(error);
            std::cout << "wrote " << options.softOverlay << " (" << label << ": " << legendText(OverlayKind::Soft)
                      << "; the rest dimmed): " << softOverlayCounts(light.report.soft) << "\n";
        }
        // The live path re-measures light 0 from the meter's cached reference: make it light 0's again.
        if (options.remeasureBench > 0 && many.lights.back().index != 0 &&
            !meter.measure(scene, *settings, camera, options.width, options.height).ok)
            return fail("--remeasure-bench: light 0 cannot be measured");
        if (options.remeasureBench > 0 &&
            !runRemeasureBench(std::cout, meter, scene, *settings, camera, options.width, options.height,
                               options.remeasureBench))
            return 1;
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
