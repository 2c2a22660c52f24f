#include "cli/measure_command.h"

#include "accuracy/accuracy_meter.h"
#include "cli/accuracy_output.h"
#include "cli/command_input.h"
#include "cli/remeasure_bench.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "image/image_io.h"
#include "scene/scene_source.h"
#include "settings/atomic_file.h"

#include <iostream>

namespace shadowlab::cli {

int runMeasure(const MeasureOptions& options) {
    std::optional<Settings> settings = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!settings) return 2;
    if (std::string error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    if (std::string error = checkMeasureMemory(options.width, options.height); !error.empty()) return fail(error);
    for (const auto& [path, option] : {std::pair{options.json, "--json"}, std::pair{options.overlay, "--overlay"},
                                       std::pair{options.causeOverlay, "--cause-overlay"}})
        if (std::string error = checkOutputFolder(path, option); !error.empty()) return fail(error);
    SceneLoadResult loaded = loadSceneForCommand(options.scene);
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;

    try {
        HeadlessContext context;
        AccuracyMeter meter;
        const Camera camera = cameraFor(settings->camera, scene, double(options.width) / options.height);
        const AccuracyReport report = meter.measure(scene, *settings, camera, options.width, options.height);
        if (!report.ok) return fail(report.error);
        for (const std::string& w : report.warnings) std::cerr << "warning: " << w << "\n";
        std::cout << "scene " << scene.name << " (" << scene.triangleCount() << " triangles)\n";
        printAccuracy(std::cout, report);
        printAccuracyCost(std::cout, report);
        if (!options.json.empty()) {
            nlohmann::json json = accuracyToJson(report);
            json["scene"] = options.scene;
            json["preset"] = options.preset;
            // replace: a scene path that is not UTF-8 is written with U+FFFD rather than throwing.
            const std::string text = json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
            if (std::string error = writeFileAtomically(options.json, text); !error.empty())
                return fail(error);
            std::cout << "wrote " << options.json << "\n";
        }
        for (const auto& [path, kind] : {std::pair{options.overlay, OverlayKind::Error},
                                         std::pair{options.causeOverlay, OverlayKind::Cause}}) {
            if (path.empty()) continue;
            const std::vector<std::uint8_t>& rgba =
                kind == OverlayKind::Error ? report.overlayRgba : report.causeOverlayRgba;
            if (std::string error = writePng(path, report.width, report.height, 4, rgba.data(), false); !error.empty())
                return fail(error);
            std::cout << "wrote " << path << " (" << legendText(kind) << "; the rest dimmed)\n";
        }
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
