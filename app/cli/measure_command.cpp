#include "cli/measure_command.h"

#include "accuracy/accuracy_meter.h"
#include "cli/accuracy_output.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "image/image_io.h"
#include "scene/scene_source.h"

#include <iostream>

namespace shadowlab::cli {

namespace {

int fail(const std::string& message) {
    std::cerr << "error: " << message << "\n";
    return 1;
}

}  // namespace

int runMeasure(const MeasureOptions& options) {
    std::optional<Settings> settings = settingsFromCli(options.preset, options.overrides);
    if (!settings) return 2;
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        return fail("--width/--height must be in [1, 16384], got " + std::to_string(options.width) + "x" +
                    std::to_string(options.height));
    for (const auto& [path, option] : {std::pair{options.json, "--json"}, std::pair{options.overlay, "--overlay"}})
        if (std::string error = checkOutputFolder(path, option); !error.empty()) return fail(error);
    SceneLoadResult loaded = loadScene(options.scene);
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;
    for (const std::string& w : scene.warnings) std::cerr << "warning: " << scene.name << ": " << w << "\n";

    try {
        HeadlessContext context;
        AccuracyMeter meter;
        const Camera camera = cameraFor(settings->camera, scene);
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
            if (std::string error = writeTextFile(options.json, json.dump(2) + "\n"); !error.empty())
                return fail(error);
            std::cout << "wrote " << options.json << "\n";
        }
        if (!options.overlay.empty()) {
            if (std::string error = writePng(options.overlay, report.width, report.height, 4,
                                             report.overlayRgba.data(), false);
                !error.empty())
                return fail(error);
            std::cout << "wrote " << options.overlay
                      << " (red = acne, blue = leak, darker = within k of a true edge, orange = faint acne, "
                         "yellow = true boundary)\n";
        }
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
